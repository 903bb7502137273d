//! The page shell: HTML escaping, the inline style sheet (screen, phone and
//! A4 print), figures. No script and no external resource: a Content
//! Security Policy that allows only inline styles and data: images keeps
//! the browser from fetching anything.

use crate::report::table::escape;
use crate::study::provenance::VERSION;

/// The style sheet: readable on a phone (fluid width, tables and code that
/// scroll sideways, SVG scaled to the width), printable on A4 (no
/// navigation, figures not split across pages, code unclipped).
pub const CSS: &str = r#"
:root { --fg: #1b1f24; --muted: #57606a; --line: #d0d7de; --head: #f3f5f7; --accent: #0072b2; }
* { box-sizing: border-box; }
html { -webkit-text-size-adjust: 100%; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
  color: var(--fg); margin: 0 auto; max-width: 1200px; padding: 1rem 1.25rem 3rem; line-height: 1.45; }
p, h1, h2, h3, h4, li, figcaption, footer { overflow-wrap: anywhere; }
h1 { font-size: 1.6rem; margin: 0.2rem 0 0.3rem; }
h2 { font-size: 1.3rem; margin-top: 2.2rem; border-bottom: 2px solid var(--accent); padding-bottom: 0.2rem; }
h3 { font-size: 1.05rem; margin: 1.4rem 0 0.5rem; }
p.prov, p.note, figcaption, .muted { color: var(--muted); font-size: 0.9rem; }
ul.verdict { padding-left: 1.2rem; }
ul.verdict li.warn { color: #a4161a; font-weight: 600; }
nav ul { display: flex; flex-wrap: wrap; gap: 0.3rem 1rem; padding: 0; list-style: none; margin: 0.6rem 0; }
nav a { color: var(--accent); text-decoration: none; }
.scroll { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; font-size: 0.88rem; margin: 0.4rem 0 0.8rem; }
th, td { border: 1px solid var(--line); padding: 0.22rem 0.5rem; text-align: right; white-space: nowrap; vertical-align: top; }
th { background: var(--head); }
td.l, th.l { text-align: left; white-space: normal; min-width: 8em; }
td .ci { display: block; color: var(--muted); font-size: 0.78rem; }
tr.ref td { background: #fffbe6; }
table.runs td.l, table.meta td.l { overflow-wrap: anywhere; }
table.designs { font-size: 0.8rem; }
table.designs th { white-space: normal; overflow-wrap: normal; word-break: keep-all; hyphens: none; }
table.designs td.l, table.designs th.l { min-width: 5em; }
table.designs td .ci { white-space: normal; }
figure { margin: 1rem 0 1.4rem; }
figure svg { display: block; max-width: 100%; height: auto; border: 1px solid var(--line); background: #fff; }
.views { display: flex; flex-wrap: wrap; gap: 1rem; }
.views figure { flex: 1 1 340px; margin: 0.4rem 0; }
.balls { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(100%, 560px), 1fr)); gap: 0.8rem; }
.ball { display: flex; gap: 0.4rem; }
.ball figure { flex: 1 1 50%; margin: 0.3rem 0; min-width: 0; }
pre { background: #f6f8fa; border: 1px solid var(--line); padding: 0.6rem; font-size: 0.8rem;
  overflow: auto; max-height: 28rem; white-space: pre; }
.two { display: grid; grid-template-columns: repeat(auto-fit, minmax(320px, 1fr)); gap: 1rem; }
.two > div { min-width: 0; }
footer { margin-top: 3rem; border-top: 1px solid var(--line); padding-top: 0.6rem; }
@media (max-width: 600px) {
  body { padding: 0.6rem 0.7rem 2rem; }
  h1 { font-size: 1.3rem; }
  th, td { padding: 0.18rem 0.35rem; font-size: 0.8rem; }
}
@page { size: A4; margin: 14mm 12mm; }
@media print {
  body { max-width: none; padding: 0; font-size: 10pt; }
  nav { display: none; }
  h2 { break-before: auto; break-after: avoid; }
  h3 { break-after: avoid; }
  figure, table, .views, .ball { break-inside: avoid; }
  pre { max-height: none; overflow: visible; white-space: pre-wrap; font-size: 7.5pt; }
  .scroll { overflow: visible; }
  table { font-size: 8pt; }
  th, td { padding: 0.1rem 0.3rem; }
  th { white-space: normal; }
  td.l, th.l { min-width: 0; }
  td .ci { font-size: 7pt; }
  table.designs { font-size: 6.5pt; }
  table.designs td.l { overflow-wrap: anywhere; }
  table.designs th { overflow-wrap: normal; word-break: keep-all; }
  table.designs th, table.designs td { padding: 0.05rem 0.15rem; }
  figure svg { border: none; }
  a { color: inherit; text-decoration: none; }
}
"#;

/// The whole document around `body`.
pub fn document(title: &str, body: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\">\n\
         <meta name=\"generator\" content=\"kinrepro {VERSION}\">\n\
         <title>{}</title>\n<style>{CSS}</style>\n</head>\n<body>\n{body}\n</body>\n</html>\n",
        escape(title)
    )
}

/// A figure holding an SVG, with an id (for the table of contents and the
/// browser test) and a caption.
pub fn figure(id: &str, svg: &str, caption: &str) -> String {
    format!(
        "<figure id=\"{}\" data-check=\"chart\">\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
        escape(id),
        strip_xml_prolog(svg),
        escape(caption)
    )
}

/// SVG text without an `<?xml ...?>` prolog (not allowed inside HTML).
pub fn strip_xml_prolog(svg: &str) -> &str {
    let s = svg.trim_start();
    match s.strip_prefix("<?xml") {
        Some(rest) => rest.find("?>").map_or(s, |i| rest[i + 2..].trim_start()),
        None => s,
    }
}
