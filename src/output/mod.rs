//! Output files written whole or not at all ([`atomic`]), and the
//! temporaries that exist meanwhile ([`temporaries`]), removed on a hard
//! exit.

pub mod atomic;
pub mod temporaries;
