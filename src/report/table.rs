//! One table type for every tabular output: columns with a header (unit in
//! brackets), an alignment and a number format; rows of cells, each row
//! optionally with a line of cells under it (the interval of a sigma) and a
//! class (HTML); free notes between rows. Rendered to aligned text without
//! borders (`comfy-table`), to CSV (the `csv` crate: quoted where needed)
//! and to an HTML table.

use std::fmt::Write as _;

use comfy_table::{CellAlignment, presets::NOTHING};

use crate::delimited::csv_cell;
use crate::report::printable::printable;

/// How a column's numbers are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Format {
    /// `{}`: Rust's shortest round-trip form.
    Plain,
    /// `{:.p$}`.
    Fixed(usize),
    /// `{:.p$e}`.
    Sci(usize),
    /// `{:e}`: the shortest round-trip form with an exponent (SI values in CSV).
    Exp,
    /// N significant digits ([`significant`]): fitted values beside their interval.
    Significant(usize),
}

/// `v` to `p` significant digits (`0.07815540470188051` to 4: `0.07816`),
/// with an exponent below 1e-4 and from 1e6 on.
pub fn significant(v: f64, p: usize) -> String {
    let p = p.max(1);
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let e = v.abs().log10().floor() as i32;
    if !(-4..6).contains(&e) {
        return format!("{v:.*e}", p - 1);
    }
    let decimals = (p as i32 - 1 - e).max(0) as usize;
    format!("{v:.decimals$}")
}

impl Format {
    fn write(self, v: f64) -> String {
        match self {
            Format::Plain => format!("{v}"),
            Format::Fixed(p) => format!("{v:.p$}"),
            Format::Sci(p) => format!("{v:.p$e}"),
            Format::Exp => format!("{v:e}"),
            Format::Significant(p) => significant(v, p),
        }
    }
}

/// One column.
#[derive(Debug, Clone, PartialEq)]
pub struct Column {
    header: String,
    left: bool,
    format: Format,
}

impl Column {
    /// A left-aligned column (names, words).
    pub fn left(header: impl Into<String>) -> Self {
        Column { header: header.into(), left: true, format: Format::Plain }
    }

    /// A right-aligned column (numbers).
    pub fn right(header: impl Into<String>) -> Self {
        Column { left: false, ..Column::left(header) }
    }

    /// Numbers with `p` decimals.
    pub fn fixed(self, p: usize) -> Self {
        self.format(Format::Fixed(p))
    }

    fn format(self, format: Format) -> Self {
        Column { format, ..self }
    }

    /// Columns from their specs, separated by `;`.
    pub fn list(specs: &str) -> Vec<Column> {
        specs.split(';').map(Column::parse).collect()
    }

    /// A column from its spec: `<` (left) or `>` (right), the header, then
    /// optionally `:` and the number format: `.N` (N decimals), `.Ne` (N
    /// decimals with an exponent), `e` (shortest with an exponent), as in
    /// Rust's format strings, or `.Ng` (N significant digits). E.g.
    /// `>F_n [N]:.6`, `<point`.
    pub fn parse(spec: &str) -> Self {
        let spec = spec.trim();
        let (head, format) = match spec.rsplit_once(':') {
            Some((h, f)) if f == "e" || f.starts_with('.') => (h, f),
            _ => (spec, ""),
        };
        let digits = |f: &str| f.trim_start_matches('.').trim_end_matches(['e', 'g']).parse().ok();
        let format = match (format, digits(format)) {
            ("e", _) => Format::Exp,
            (f, Some(p)) if f.ends_with('e') => Format::Sci(p),
            (f, Some(p)) if f.ends_with('g') => Format::Significant(p),
            (_, Some(p)) => Format::Fixed(p),
            _ => Format::Plain,
        };
        let col = match head.strip_prefix('>') {
            Some(h) => Column::right(h),
            None => Column::left(head.strip_prefix('<').unwrap_or(head)),
        };
        col.format(format)
    }
}

/// One cell: a number (written in its column's format), text, or a
/// missing value (`-` in text and HTML, empty in CSV).
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    Num(f64),
    Text(String),
    Missing,
}

impl From<f64> for Cell {
    fn from(v: f64) -> Self {
        Cell::Num(v)
    }
}

impl From<Option<f64>> for Cell {
    fn from(v: Option<f64>) -> Self {
        v.map_or(Cell::Missing, Cell::Num)
    }
}

/// Text cells from strings and counts.
macro_rules! text_cell {
    ($($t:ty),*) => {$(
        impl From<$t> for Cell {
            fn from(v: $t) -> Self {
                Cell::Text(v.to_string())
            }
        }
    )*};
}
text_cell!(String, &str, &String, usize);

/// A row's cells from values of mixed types: `cells![i + 1, name, x]`.
macro_rules! cells {
    ($($c:expr),* $(,)?) => { vec![$($crate::report::table::Cell::from($c)),*] };
}
pub(crate) use cells;

/// One row: its cells, the cells under it (text: a line of its own; HTML:
/// under each cell's value) and its HTML class.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    cells: Vec<Cell>,
    under: Vec<String>,
    class: Option<&'static str>,
}

impl Row {
    /// Text under the cells, one per column ("" for none).
    pub fn under(&mut self, under: Vec<String>) -> &mut Self {
        self.under = under;
        self
    }

    /// The HTML class of the row (e.g. `ref` for a highlighted reference).
    pub fn class(&mut self, class: &'static str) -> &mut Self {
        self.class = Some(class);
        self
    }
}

#[derive(Debug, Clone, PartialEq)]
enum Line {
    Row(Row),
    /// Free text across the table (no column).
    Note(String),
}

/// A table: columns, then rows and notes in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    columns: Vec<Column>,
    lines: Vec<Line>,
    indent: usize,
}

impl Table {
    /// A table of the columns `specs` ([`Column::list`]).
    pub fn new(specs: &str) -> Self {
        Table::of(Column::list(specs))
    }

    pub fn of(columns: impl IntoIterator<Item = Column>) -> Self {
        Table { columns: columns.into_iter().collect(), lines: Vec::new(), indent: 0 }
    }

    /// More columns after these.
    pub fn with(mut self, columns: impl IntoIterator<Item = Column>) -> Self {
        self.columns.extend(columns);
        self
    }

    /// Indent every text line by `n` spaces.
    pub fn indent(mut self, n: usize) -> Self {
        self.indent = n;
        self
    }

    /// Add a row (one cell per column).
    pub fn row(&mut self, cells: Vec<Cell>) -> &mut Row {
        debug_assert_eq!(cells.len(), self.columns.len(), "one cell per column");
        self.lines.push(Line::Row(Row { cells, under: Vec::new(), class: None }));
        match self.lines.last_mut() {
            Some(Line::Row(r)) => r,
            _ => unreachable!("a row was just pushed"),
        }
    }

    /// True without rows or notes.
    pub fn is_empty(&self) -> bool {
        self.lines.is_empty()
    }

    /// Add a line of free text after the rows so far.
    pub fn note(&mut self, text: impl Into<String>) {
        self.lines.push(Line::Note(text.into()));
    }

    /// The cells of a row as text; `missing` for a missing value.
    fn texts(&self, row: &Row, missing: &str) -> Vec<String> {
        (row.cells.iter().zip(&self.columns))
            .map(|(c, col)| match c {
                Cell::Num(v) => col.format.write(*v),
                Cell::Text(t) => t.clone(),
                Cell::Missing => missing.to_string(),
            })
            .collect()
    }

    /// Aligned text without borders, one space between columns, trailing
    /// spaces trimmed, notes on lines of their own.
    pub fn text(&self) -> String {
        let mut t = comfy_table::Table::new();
        t.load_style(NOTHING);
        t.set_header(self.columns.iter().map(|c| c.header.as_str()));
        let mut after: Vec<Vec<&str>> = vec![Vec::new()];
        for line in &self.lines {
            match line {
                Line::Row(r) => {
                    let texts = self.texts(r, "-");
                    t.add_row(texts.iter().map(|c| printable(c).into_owned()).collect::<Vec<_>>());
                    after.push(Vec::new());
                    if !r.under.is_empty() {
                        t.add_row(r.under.clone());
                        after.push(Vec::new());
                    }
                }
                Line::Note(n) => after.last_mut().map_or((), |a| a.push(n)),
            }
        }
        for (col, c) in t.column_iter_mut().zip(&self.columns) {
            col.set_padding((0, 1));
            col.set_cell_alignment(if c.left { CellAlignment::Left } else { CellAlignment::Right });
        }
        let pad = " ".repeat(self.indent);
        let mut s = String::new();
        for (line, notes) in t.lines().zip(&after) {
            let _ = writeln!(s, "{pad}{}", line.trim_end());
            for n in notes {
                let _ = writeln!(s, "{pad}{}", printable(n));
            }
        }
        s
    }

    /// CSV: the header, then every row and the cells under it (notes are
    /// left out), quoted where a cell needs it (the `csv` crate).
    pub fn csv(&self) -> String {
        let mut w = csv::Writer::from_writer(Vec::new());
        let mut rows = vec![self.columns.iter().map(|c| c.header.clone()).collect()];
        for line in &self.lines {
            if let Line::Row(r) = line {
                rows.push(self.texts(r, ""));
                rows.extend((!r.under.is_empty()).then(|| r.under.clone()));
            }
        }
        // Writing to memory cannot fail, and the cells are UTF-8.
        for r in rows {
            let _ = w.write_record(r.iter().map(|c| csv_cell(c).into_owned()));
        }
        String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
    }

    /// An HTML table (`class` on the table element, "" for none): the
    /// header, then the rows, the cells under a row in a `ci` span under
    /// each value, notes as rows across every column.
    pub fn html(&self, class: &str) -> String {
        let l = |c: &Column| if c.left { " class=\"l\"" } else { "" };
        let class = if class.is_empty() { String::new() } else { format!(" class=\"{class}\"") };
        let mut s = format!("<div class=\"scroll\"><table{class} data-check=\"table\"><thead><tr>");
        for c in &self.columns {
            let _ = write!(s, "<th{}>{}</th>", l(c), escape(&c.header));
        }
        s.push_str("</tr></thead><tbody>\n");
        for line in &self.lines {
            let r = match line {
                Line::Row(r) => r,
                Line::Note(n) => {
                    let n = escape(n);
                    let span = self.columns.len();
                    let _ = writeln!(s, "<tr><td class=\"l\" colspan=\"{span}\">{n}</td></tr>");
                    continue;
                }
            };
            match r.class {
                Some(c) => {
                    let _ = write!(s, "<tr class=\"{c}\">");
                }
                None => s.push_str("<tr>"),
            }
            for (k, (text, col)) in self.texts(r, "-").iter().zip(&self.columns).enumerate() {
                let under = match r.under.get(k) {
                    Some(u) if !u.is_empty() => format!("<span class=\"ci\">{}</span>", escape(u)),
                    _ => String::new(),
                };
                let _ = write!(s, "<td{}>{}{under}</td>", l(col), escape(text));
            }
            s.push_str("</tr>\n");
        }
        s.push_str("</tbody></table></div>\n");
        s
    }
}

/// Escape text for HTML element content and attribute values.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}
