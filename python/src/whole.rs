//! Whole-number arguments (counts, seeds, indices): an `int` >= 0. A
//! negative, fractional or non-integer value raises a `TypeError` that
//! pyo3 prefixes with the argument's name (`argument 'samples': -1 is
//! negative: ...`); pyo3's own conversion to an unsigned integer raises a
//! bare `OverflowError` that names nothing.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyBool;

/// An `int` >= 0 that fits `T`.
pub struct Whole<T>(T);

impl<T> Whole<T> {
    /// A default value of a signature.
    pub const fn of(v: T) -> Self {
        Whole(v)
    }

    pub fn get(self) -> T {
        self.0
    }
}

impl<'a, 'py, T: TryFrom<u64>> FromPyObject<'a, 'py> for Whole<T> {
    type Error = PyErr;

    fn extract(obj: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        let bad = |why: String| PyTypeError::new_err(why);
        if obj.is_instance_of::<PyBool>() {
            return Err(bad("expected a whole number >= 0, got a bool".into()));
        }
        let v: i128 = obj.extract().map_err(|_| {
            let t = obj.get_type().name().map_or("?".into(), |n| n.to_string());
            bad(format!("expected a whole number >= 0 (an int), got {t}"))
        })?;
        if v < 0 {
            return Err(bad(format!("{v} is negative: expected a whole number >= 0")));
        }
        let too_large = || bad(format!("{v} is too large"));
        let v = u64::try_from(v).map_err(|_| too_large())?;
        T::try_from(v).map(Whole).map_err(|_| too_large())
    }
}
