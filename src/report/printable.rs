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
    // The control characters (Unicode Cc) are U+0000-U+001F, U+007F and
    // U+0080-U+009F, whose UTF-8 begins with the byte 0xC2: a text without
    // such a byte has none, and a byte scan decides the common case (a
    // whole output of several megabytes) without decoding it.
    let kept = |b: u8| keep_lines && (b == b'\n' || b == b'\t');
    let suspect = |b: u8| (b < 0x20 && !kept(b)) || b == 0x7f || b == 0xc2;
    // In blocks without a short cut inside one, so that the scan vectorises.
    let clean = s.as_bytes().chunks(64).all(|b| !b.iter().fold(false, |a, &b| a | suspect(b)));
    if clean || !s.chars().any(bad) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The byte scan decides as the character rule does: texts with and
    /// without control characters, with 0xC2 in a printable character
    /// (the degree sign, U+00B0) and in a control one (NEL, U+0085).
    #[test]
    fn byte_scan_agrees_with_the_character_rule() {
        let texts = [
            "plain",
            "a\nb\tc",
            "30 \u{b0}C",
            "x\u{85}y",
            "\u{1b}[31m",
            "\u{7f}",
            "\r",
            "",
            "\u{9f}",
            "\u{a0}\u{c2}\u{2028}",
        ];
        for keep in [false, true] {
            for t in texts {
                let bad = |c: char| c.is_control() && !(keep && (c == '\n' || c == '\t'));
                let expected: String = t
                    .chars()
                    .map(|c| if bad(c) { c.escape_default().to_string() } else { c.to_string() })
                    .collect();
                assert_eq!(escaped(t, keep), expected, "{t:?} keep_lines {keep}");
            }
        }
    }
}
