//! The command line's flags in two layers (ripgrep's split of low- and
//! high-level arguments): [`low`] and [`low_study`] are what clap parses,
//! one struct per verb; [`high`] checks them, once, into the typed options
//! the commands use ([`high::Checked`]: the arguments and what was made of
//! them); [`unused`] refuses flags that would have no effect. A flag's value
//! or a combination of flags is checked nowhere else.

pub mod high;
pub mod low;
pub mod low_study;
pub mod unused;

pub use low::Cli;
