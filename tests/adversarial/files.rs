//! Output files, signals, size bounds and panics (issue 28 items 1-2).

#[allow(unused_imports)]
use crate::common;
