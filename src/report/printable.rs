//! Text from a user's files (scene names, evaluation-point names, paths)
//! as shown on a terminal: control characters (NUL, BEL, ESC, CR, line
//! breaks, ...) are written as Rust escapes (`\u{1b}`, `\r`), so that a
//! name can neither move the cursor, recolour the terminal, ring the bell
//! nor hide or forge a line of output.

use std::borrow::Cow;

/// `s` with every control character escaped (line breaks too: for one
/// name or one line of text).
pub fn printable(s: &str) -> Cow<'_, str> {
    escaped(s, false)
}

/// `s` with every control character but the line break and the tab
/// escaped (for a whole output of several lines).
pub fn printable_lines(s: &str) -> Cow<'_, str> {
    escaped(s, true)
}

fn escaped(s: &str, keep_lines: bool) -> Cow<'_, str> {
    let bad = |c: char| c.is_control() && !(keep_lines && (c == '\n' || c == '\t'));
    if !s.chars().any(bad) {
        return s.into();
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if bad(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out.into()
}
