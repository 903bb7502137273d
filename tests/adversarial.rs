//! Adversarial inputs (issue 28): each case is a command line a user or a
//! script could give, and the test asserts that kinrepro refuses it clearly
//! (one line naming the file or option, the field and the reason, non-zero
//! exit), or handles it without destroying, hanging or printing a number it
//! should not. Future work extends the part files below.

mod common;

#[path = "adversarial/files.rs"]
mod files;
#[path = "adversarial/geometry.rs"]
mod geometry;
#[path = "adversarial/inputs.rs"]
mod inputs;
#[path = "adversarial/messages.rs"]
mod messages;
#[path = "adversarial/replay.rs"]
mod replay;
#[path = "adversarial/verdicts.rs"]
mod verdicts;
