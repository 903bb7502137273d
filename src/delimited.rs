//! Reading the delimited text files a person writes or a spreadsheet
//! exports (load histories, measurements, reference values): a byte-order
//! mark is dropped, blank lines are skipped, lines starting with `#` are
//! comments, and every other line is one CSV record read by the `csv` crate
//! (quoted fields, `""` inside quotes, cells trimmed). The delimiter is a
//! comma, semicolon or tab: the one of the three the first record holds
//! most of (a comma on a tie or when there is none), unless given.

use crate::param::{Param, ParamError};

/// One record: its line in the file (1-based), the line as written
/// (trimmed) and its cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub line: usize,
    pub text: String,
    pub cells: Vec<String>,
}

/// The lines of a delimited text.
#[derive(Debug, Clone, PartialEq)]
pub struct Delimited {
    pub delimiter: u8,
    /// `#` lines: the line number and the text after `#`.
    pub comments: Vec<(usize, String)>,
    pub records: Vec<Record>,
}

/// A delimiter by name (`delimiter`): one ASCII character other than `"`
/// and `#`, or `tab` (also `\t`), `comma`, `semicolon`.
pub fn delimiter_named(s: &str) -> Result<u8, ParamError> {
    match s {
        "tab" | "\\t" | "\t" => Ok(b'\t'),
        "comma" => Ok(b','),
        "semicolon" => Ok(b';'),
        _ if s.len() == 1 && s.is_ascii() && s != "\"" && s != "#" => Ok(s.as_bytes()[0]),
        _ => Err(ParamError::new(
            Param::Delimiter,
            format!(
                "{} `{s}`: give one character such as `,` or `;`, or `tab` (not `\"` or `#`)",
                Param::Delimiter
            ),
        )),
    }
}

/// Split `text` into comments and records; `delimiter` None: detected from
/// the first record ([`detect_delimiter`]).
pub fn read(text: &str, delimiter: Option<u8>) -> Delimited {
    let text = crate::input::without_bom(text);
    let mut comments = Vec::new();
    let mut lines = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if let Some(c) = line.strip_prefix('#') {
            comments.push((i + 1, c.to_string()));
        } else if !line.is_empty() {
            lines.push((i + 1, line));
        }
    }
    let delimiter =
        delimiter.unwrap_or_else(|| lines.first().map_or(b',', |(_, l)| detect_delimiter(l)));
    let records = lines
        .into_iter()
        .map(|(line, text)| Record { line, text: text.to_string(), cells: split(text, delimiter) })
        .collect();
    Delimited { delimiter, comments, records }
}

/// The delimiter a header line is separated by: the most frequent of comma,
/// semicolon and tab (a comma on a tie or when there is none).
pub fn detect_delimiter(header: &str) -> u8 {
    let count = |d: u8| header.bytes().filter(|b| *b == d).count();
    [b';', b'\t'].into_iter().fold(b',', |best, d| if count(d) > count(best) { d } else { best })
}

/// The cells of one line as a CSV record, trimmed. Reading a line of text
/// cannot fail (no I/O, valid UTF-8, any number of fields).
fn split(line: &str, delimiter: u8) -> Vec<String> {
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(delimiter)
        .has_headers(false)
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(line.as_bytes());
    let record = reader.records().next().and_then(Result::ok);
    record.map_or_else(Vec::new, |r| r.iter().map(str::to_string).collect())
}

/// A cell as written to a CSV file, safe to open in a spreadsheet: a cell
/// that is not a number and begins with `=`, `+`, `-`, `@`, a tab or a
/// carriage return would be run as a formula (CSV injection), so it gets a
/// leading `'`, which spreadsheets show as text (OWASP, "CSV Injection").
/// Numbers such as `-1.5e-9` stay as they are.
pub fn csv_cell(cell: &str) -> std::borrow::Cow<'_, str> {
    let risky = cell.starts_with(['=', '+', '-', '@', '\t', '\r']);
    if risky && cell.trim().parse::<f64>().is_err() {
        format!("'{cell}").into()
    } else {
        cell.into()
    }
}
