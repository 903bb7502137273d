//! `sweep --html` in Chromium: the design review report of a sweep.

use super::*;

/// `sweep --html`: a report fit for a design review, self-contained: the
/// provenance (version, seed), the table of design points with the
/// sweep JSON's numbers and the reason of an invalid point, the charts
/// with units on the axes and the Pareto front labelled by the table's #,
/// the base scene's text and its coupling drawn with the scene's
/// dimensions; in Chromium every element visible, the Pareto labels
/// neither overlapping nor leaving their chart, and no table wider than
/// its box at 1400 px nor under the print rules at A4's width.
#[test]
fn sweep_html_is_a_design_review_report_in_chromium() {
    let tmp = tempfile::tempdir().unwrap();
    let html_file = tmp.path().join("report.html");
    let s1 = scene("01_maxwell_vgroove_steel.toml");
    // `tubes` is no groove: those two points are invalid, with a reason.
    let (ok, json, err) = kinrepro(&[
        "sweep",
        s1.to_str().unwrap(),
        "--set",
        "preload.force=10,20",
        "--set",
        "coupling.groove=planes,cylinders,tubes",
        "--set",
        "coupling.groove_element_diameter=0.006",
        "--samples",
        "10",
        "--seed",
        "7",
        "--format",
        "json",
        "--html",
        html_file.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let sweep: serde_json::Value = serde_json::from_str(&json).unwrap();
    let html = std::fs::read_to_string(&html_file).unwrap();
    self_contained(&html);
    sweep_static_checks(&html, &sweep, &std::fs::read_to_string(&s1).unwrap());
    let Some(exe) = chromium() else { return };
    // sigma against each of 3 fields, the Pareto front, the points not
    // evaluated; the base coupling: a layout and a top and a side view of
    // each of 3 balls.
    let expect = Expect { charts: 5, drawings: 7, min_tables: 2, scenes: 1 };
    browser_checks(&exe, tmp.path(), &html, &expect);
    let dom = probe_dom(&exe, tmp.path(), &html, "1400,2000");
    let r = probe_result(&dom, "1400");
    tables_fit(&r, "1400");
    let front = sweep["designs"].as_array().unwrap().iter();
    let front = front.filter(|d| d["pareto"] == true).count();
    labels_apart(&r, "sweep-pareto", front);
    // The print rules on screen at A4's width less its margins (703 px).
    let print = html.replace("@media print", "@media all");
    tables_fit(&probe_result(&probe_dom(&exe, tmp.path(), &print, "703,2000"), "A4"), "A4 print");
    let want = study_scenes::dimensions(&std::fs::read_to_string(&s1).unwrap());
    study_scenes::drawing_labels(&r, "sweep", &want);
}

/// Text as HTML escapes it (independently of the report's escaping).
fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
        .replace('\'', "&#39;")
}

/// Provenance, units, the table's rows against the sweep JSON, the
/// Pareto labels, the scene text.
fn sweep_static_checks(html: &str, sweep: &serde_json::Value, scene_text: &str) {
    let version = env!("CARGO_PKG_VERSION");
    for s in [
        format!("<td class=\"l\">kinrepro version</td><td class=\"l\">{version}</td>"),
        "<td class=\"l\">seed</td><td class=\"l\">7</td>".to_string(),
        "<td class=\"l\">samples per design point</td><td class=\"l\">10</td>".to_string(),
        "<td class=\"l\">design</td><td class=\"l\">grid, 6 points</td>".to_string(),
        "preload.force [N] = 10,20".to_string(),
        // A field's header breaks between words only: after a dot or an
        // underscore.
        "<th class=\"l\">coupling.\u{200B}groove_\u{200B}element_\u{200B}diameter [m]</th>"
            .to_string(),
        // Sections titled by what they show, legends with units.
        "<h3>σ against preload.force [N]</h3>".to_string(),
        "<h3>Pareto front: the largest translational σ against k_min</h3>".to_string(),
        "preload.force = 10 N, ".to_string(),
        "coupling.groove_element_diameter = 0.006 m".to_string(),
        "<th>σ_x [nm]</th>".to_string(),
        "<th>σ_φz [nrad]</th>".to_string(),
        "<th>k_min [N/µm]</th>".to_string(),
        // Chart axes with units.
        ">\npreload.force [N]\n</text>".to_string(),
        ">\nlowest principal translational stiffness k_min [N/µm]\n</text>".to_string(),
        format!("<pre data-check=\"scene\">{}</pre>", html_escape(scene_text)),
    ] {
        assert!(html.contains(&s), "missing {s}");
    }
    let designs = sweep["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 6);
    let table = &html[html.find("<table class=\"designs\"").unwrap()..];
    let table = &table[..table.find("</table>").unwrap()];
    for d in designs {
        let i = d["index"].as_u64().unwrap();
        let groove = d["values"]["coupling.groove"].as_str().unwrap();
        let row = format!("<tr><td>{i}</td><td class=\"l\">");
        let at = table.find(&row).unwrap_or_else(|| panic!("no row #{i}"));
        let row = &table[at..at + table[at..].find("</tr>").unwrap()];
        assert!(row.contains(&format!(">{groove}</td>")), "{row}");
        if d["status"] == "ok" {
            let sx = d["points"][0]["sigma"]["x_nm"].as_f64().unwrap();
            let k = d["principal_stiffness_n_per_m"][0].as_f64().unwrap() * 1e-6;
            assert!(row.contains(&format!("<td>{sx:.3}<span")), "{row}");
            assert!(row.contains(&format!("<td>{k:.2}</td>")), "{row}");
            let front = d["pareto"] == true;
            assert_eq!(row.contains(">front</td>"), front, "{row}");
            // The Pareto chart labels a front point with its #.
            assert_eq!(html.contains(&format!(">\n#{i}\n</text>")), front, "#{i}");
        } else {
            assert_eq!(groove, "tubes");
            let reason = html_escape(d["status"].as_str().unwrap());
            assert!(reason.starts_with("invalid: coupling.groove"), "{reason}");
            assert!(row.contains(&format!("<td class=\"l\">{reason}</td>")), "{row}");
        }
    }
}

/// The `#N` labels in the chart `figure`: `n` of them, no two
/// overlapping, each inside its SVG.
fn labels_apart(r: &serde_json::Value, figure: &str, n: usize) {
    let labels: Vec<[f64; 4]> = r["labels"][figure]
        .as_array()
        .unwrap_or_else(|| panic!("no chart {figure}: {r}"))
        .iter()
        .map(|b| [0, 1, 2, 3].map(|k| b[k].as_f64().unwrap()))
        .collect();
    assert_eq!(labels.len(), n, "{figure}");
    let svg = [0, 1, 2, 3].map(|k| r["label_svg"][figure][k].as_f64().unwrap());
    for (i, a) in labels.iter().enumerate() {
        assert!(
            a[0] >= svg[0] && a[1] >= svg[1] && a[2] <= svg[2] && a[3] <= svg[3],
            "{figure}: label {a:?} outside {svg:?}"
        );
        for b in &labels[i + 1..] {
            let apart = a[2] <= b[0] || b[2] <= a[0] || a[3] <= b[1] || b[3] <= a[1];
            assert!(apart, "{figure}: labels {a:?} and {b:?} overlap");
        }
    }
}
