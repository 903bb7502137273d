//! Validity warnings, flags without effect, and errors that name the option, field and reason (issue 28 items 6-7).

#[allow(unused_imports)]
use crate::common;
