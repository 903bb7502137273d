//! The command line's error: one line, what the library or a check of the
//! flags said, with where it happened. Any library error converts into it
//! (`?`), keeping its message; [`Context::context`] puts where in front
//! (`"{where}: {message}"`); [`usage!`] is a check of the flags themselves.

use std::fmt::{self, Display};

/// A failed command: the line `main` prints after `error: `.
#[derive(Debug)]
pub struct Error(String);

impl Error {
    pub fn new(message: impl Display) -> Self {
        Error(message.to_string())
    }
}

impl Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl<E: std::error::Error> From<E> for Error {
    fn from(e: E) -> Self {
        Error(e.to_string())
    }
}

pub type Result<T = ()> = std::result::Result<T, Error>;

/// Say where an error happened: `result.context(file)?`.
pub trait Context<T> {
    fn context(self, context: impl Display) -> Result<T>;
}

impl<T, E: Into<Error>> Context<T> for std::result::Result<T, E> {
    fn context(self, context: impl Display) -> Result<T> {
        self.map_err(|e| Error(format!("{context}: {}", e.into())))
    }
}

/// A check of the flags failed: return the formatted message.
macro_rules! usage {
    ($($arg:tt)*) => {
        return Err($crate::error::Error::new(format!($($arg)*)))
    };
}
pub(crate) use usage;
