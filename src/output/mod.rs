//! Output files written whole or not at all ([`atomic`]), never over an
//! input of the same command ([`inputs`]), and the temporaries that exist
//! meanwhile ([`temporaries`]), removed on a hard exit.

pub mod atomic;
pub mod inputs;
pub mod temporaries;
