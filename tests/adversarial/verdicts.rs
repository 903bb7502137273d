//! One verdict for a coupling that cannot seat; validation of every file kinrepro reads; text hygiene (issue 28 items 3-5).

#[allow(unused_imports)]
use crate::common;
