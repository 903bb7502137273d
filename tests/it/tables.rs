//! The table type renders the same cells to text, CSV and HTML; CSV cells
//! round-trip through the `csv` crate; the delimited-text readers (load
//! history, reference values) take semicolons, quoted headers and a
//! byte-order mark; DOF and input names read back to what wrote them.

use kinrepro::contact::history::parse_history_csv;
use kinrepro::dof::{Dof, Dofs, PointPose};
use kinrepro::report::html::parse_reference;
use kinrepro::report::table::{Cell, Table};
use kinrepro::study::inputs::Input;

/// A table with a left text column, a fixed-decimal column, an exponent
/// column and a missing value.
fn sample() -> Table {
    let mut t = Table::new("<name; >x [nm]:.3; >c [m/N]:.2e");
    t.row(vec![Cell::from("a"), Cell::from(1.23456), Cell::from(2.5e-9)]);
    t.row(vec![Cell::from("bb"), Cell::from(-10.0), Cell::from(None)]);
    t
}

const CELLS: [[&str; 3]; 2] = [["a", "1.235", "2.50e-9"], ["bb", "-10.000", "-"]];

#[test]
fn text_csv_and_html_hold_the_same_cells() {
    let t = sample();
    let text = t.text();
    let lines: Vec<Vec<&str>> = text.lines().map(|l| l.split_whitespace().collect()).collect();
    assert_eq!(lines[0], ["name", "x", "[nm]", "c", "[m/N]"]);
    for (row, want) in lines[1..].iter().zip(CELLS) {
        assert_eq!(row, &want);
    }
    // Right-aligned numbers end in one column, under the header's end.
    let end = |l: &str, v: &str| l.find(v).unwrap() + v.len();
    let e: Vec<usize> =
        (text.lines().zip(["[nm]", "1.235", "-10.000"])).map(|(l, v)| end(l, v)).collect();
    assert!(e[0] == e[1] && e[1] == e[2], "{text}");

    let csv = t.csv();
    let mut r = csv::Reader::from_reader(csv.as_bytes());
    let head: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(head, ["name", "x [nm]", "c [m/N]"]);
    let rows: Vec<Vec<String>> =
        (r.records()).map(|x| x.unwrap().iter().map(String::from).collect()).collect();
    assert_eq!(rows[0], CELLS[0]);
    // A missing value is an empty CSV field.
    assert_eq!(rows[1], ["bb", "-10.000", ""]);

    let html = t.html("");
    for row in CELLS {
        let cells: String = row.iter().map(|c| format!(">{c}</td>")).collect();
        let tds: Vec<&str> = cells.split("</td>").filter(|c| !c.is_empty()).collect();
        for c in tds {
            assert!(html.contains(&format!("{c}</td>")), "{c} in {html}");
        }
    }
    assert_eq!(html.matches("<tr>").count(), 3, "{html}");
}

#[test]
fn csv_cells_with_commas_quotes_and_newlines_round_trip() {
    let tricky = ["a, b", "say \"hi\"", "two\nlines", "plain"];
    let mut t = Table::new("<text; >n");
    for (i, s) in tricky.iter().enumerate() {
        t.row(vec![Cell::from(*s), Cell::from(i)]);
    }
    let csv = t.csv();
    let mut r = csv::Reader::from_reader(csv.as_bytes());
    let back: Vec<(String, String)> = (r.records())
        .map(|x| {
            let x = x.unwrap();
            (x[0].to_string(), x[1].to_string())
        })
        .collect();
    assert_eq!(back.len(), tricky.len());
    for (i, (s, n)) in back.iter().enumerate() {
        assert_eq!(s, tricky[i]);
        assert_eq!(n, &i.to_string());
    }
    // HTML escapes what it must.
    assert!(t.html("").contains("say &quot;hi&quot;"));
}

#[test]
fn notes_and_rows_under_keep_their_place() {
    let mut t = Table::new("<k; >v:.1");
    t.row(vec![Cell::from("a"), Cell::from(1.0)]).under(vec![String::new(), "[0.5, 2]".into()]);
    t.note("a note");
    t.row(vec![Cell::from("b"), Cell::from(2.0)]);
    let lines: Vec<String> = t.text().lines().map(|l| l.trim().to_string()).collect();
    assert_eq!(lines, ["k        v", "a      1.0", "[0.5, 2]", "a note", "b      2.0"]);
    let html = t.html("x");
    assert!(html.contains("<td>1.0<span class=\"ci\">[0.5, 2]</span></td>"), "{html}");
    assert!(html.contains("colspan=\"2\">a note</td>"), "{html}");
}

#[test]
fn history_reads_semicolons_quoted_headers_and_a_bom() {
    let plain = "# a history\nP_N,Qx_N,Qy_N\n1.0,0.1,0\n\n2,0.2,-0.1\n";
    let want = parse_history_csv(plain, "h.csv").unwrap();
    assert_eq!(want.len(), 2);
    assert_eq!(want[1].line, 5);
    assert_eq!(want[1].load.tangential_force, [0.2, -0.1]);
    for text in [
        plain.replace(',', ";"),
        plain.replace("P_N,Qx_N,Qy_N", "\"P_N\",\"Qx_N\",\"Qy_N\""),
        plain.replace(',', ";").replace("P_N;Qx_N;Qy_N", "\"P_N\";\"Qx_N\";\"Qy_N\""),
        format!("\u{feff}{plain}"),
        plain.replace(',', "\t"),
    ] {
        assert_eq!(parse_history_csv(&text, "h.csv").unwrap(), want, "{text:?}");
    }
    let e = parse_history_csv("P_N;Qx_N\n1;0\n", "h.csv").unwrap_err();
    assert_eq!(e.to_string(), "h.csv:1: header `P_N;Qx_N` must be `P_N,Qx_N,Qy_N`");
    let e = parse_history_csv("P_N;Qx_N;Qy_N\n1;abc;0\n", "h.csv").unwrap_err();
    assert!(e.to_string().starts_with("h.csv:2: column Qx_N: `abc`"), "{e}");
}

#[test]
fn reference_reads_quotes_empty_cells_semicolons_and_rejects_bad_numbers() {
    let header = ["label", "scene", "point"]
        .map(String::from)
        .into_iter()
        .chain(Dof::ALL.map(Dof::key))
        .collect::<Vec<_>>()
        .join(",");
    let text = format!("# paper\n{header}\n\"paper, FE\",01_a,centre,6.2,6.2,3.8,139.7,139.7,\n");
    let rows = parse_reference(&text, "r.csv").unwrap();
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0].label, "paper, FE");
    assert_eq!(rows[0].sigma[0], Some(6.2));
    assert_eq!(rows[0].sigma[5], None);
    let semi = text.replace(',', ";").replace("\"paper; FE\"", "\"paper, FE\"");
    assert_eq!(parse_reference(&semi, "r.csv").unwrap(), rows);
    let bad = text.replace("3.8", "abc");
    let e = parse_reference(&bad, "r.csv").unwrap_err().to_string();
    assert!(e.contains("r.csv:3") && e.contains(&Dof::Z.key()), "{e}");
    let neg = text.replace("3.8", "-1");
    assert!(parse_reference(&neg, "r.csv").is_err());
    assert!(parse_reference("x,y\n", "r.csv").is_err());
}

#[test]
fn dof_names_units_and_keys_agree() {
    for d in Dof::ALL {
        assert_eq!(Dof::ALL[d.index()], d);
        assert_eq!(Dof::from_name(d.name()), Some(d));
        assert_eq!(d.si_key(), format!("{}_{}", d.name(), d.si_unit()));
        assert_eq!(d.key(), format!("{}_{}", d.name(), d.unit()));
        assert_eq!(serde_json::to_value(d).unwrap(), d.name());
    }
    // The JSON keys of `Dofs` and `PointPose` are the DOFs' keys, in order.
    let order = |json: String, keys: [String; 6]| {
        let at: Vec<usize> =
            keys.iter().map(|k| json.find(&format!("\"{k}\":")).unwrap()).collect();
        assert!(at.windows(2).all(|w| w[0] < w[1]), "{json}");
        assert_eq!(json.matches(':').count(), 6, "{json}");
    };
    order(serde_json::to_string(&Dofs::from_si([1e-9; 6])).unwrap(), Dof::ALL.map(Dof::key));
    let p = PointPose::from_components([2.0; 6]);
    order(serde_json::to_string(&p).unwrap(), Dof::ALL.map(Dof::si_key));
    assert!(Dofs::from_si([1e-9; 6]).values().iter().all(|x| *x == 1.0));
}

#[test]
fn every_input_name_reads_back_to_its_input() {
    let mut all = Vec::new();
    for k in 0..12 {
        all.extend([Input::Mu(k), Input::BallDiameter(k)]);
        all.extend([Input::SurfaceNormal(k), Input::SurfaceTilt(k)]);
        all.extend((0..3).flat_map(|a| [Input::BallPosition(k, a), Input::GroovePosition(k, a)]));
        all.extend((0..2).flat_map(|a| [Input::PreloadOffset(k, a), Input::PreloadTilt(k, a)]));
    }
    all.extend((0..6).map(Input::Start));
    let mut names: Vec<String> = all.iter().map(Input::name).collect();
    for (i, n) in all.iter().zip(&names) {
        assert_eq!(Input::from_name(n), Some(*i), "{n}");
        let json = serde_json::to_string(i).unwrap();
        assert_eq!(json, format!("\"{n}\""));
        assert_eq!(serde_json::from_str::<Input>(&json).unwrap(), *i);
    }
    names.sort();
    names.dedup();
    assert_eq!(names.len(), all.len(), "names are distinct");
    assert_eq!(Input::from_name("mu_0"), None);
    assert_eq!(Input::from_name("preload_z_m"), None);
    assert!(serde_json::from_str::<Input>("\"friction\"").is_err());
}

/// Fitted values beside their interval: 4 significant digits whatever the
/// magnitude, each the value within half a unit of its last digit.
#[test]
fn significant_digits_keep_four_whatever_the_magnitude() {
    use kinrepro::report::table::significant;
    for (v, want) in [
        (0.07815540470188051, "0.07816"),
        (0.5, "0.5000"),
        (526.3845, "526.4"),
        (2.5e-8, "2.500e-8"),
        (-1.23456, "-1.235"),
        (0.0, "0"),
    ] {
        let s = significant(v, 4);
        assert_eq!(s, want, "{v}");
        let back: f64 = s.parse().unwrap();
        let mantissa = s.split('e').next().unwrap();
        let digits = mantissa.chars().filter(char::is_ascii_digit).collect::<String>();
        let sig = digits.trim_start_matches('0').len();
        assert!(v == 0.0 || sig == 4, "{s}");
        // Half a unit of the 4th digit: at most 5e-4 relative.
        assert!((back - v).abs() <= 5e-4 * v.abs(), "{v} {s}");
    }
    // In a table: the `.4g` column spec.
    let mut t = Table::new("<name; >spread:.4g");
    t.row(vec![Cell::from("a"), Cell::from(0.07815540470188051)]);
    assert!(t.text().contains("0.07816") && !t.text().contains("0.078155"));
}
