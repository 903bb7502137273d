//! The coupling drawings' force arrows read back against the preload.

use super::*;

/// The drawn contact forces are to scale: in the side views (z up) the
/// vertical components of the six force arrows, read back through the force
/// bar, add up to the preload (equilibrium of the moving half: sum of
/// N n + T = -F_p), and in the top views the horizontal ones to zero.
#[test]
fn drawn_contact_forces_balance_the_preload() {
    let tmp = tempfile::tempdir().unwrap();
    for name in ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml"] {
        let html = tmp.path().join(format!("{name}.html"));
        let (ok, _, err) = kinrepro(&[
            "study",
            scene(name).to_str().unwrap(),
            "--samples",
            "10",
            "--html",
            html.to_str().unwrap(),
        ]);
        assert!(ok, "{err}");
        let text = std::fs::read_to_string(&html).unwrap();
        let mut sum = [0.0f64; 3];
        for view in ["top", "side"] {
            for b in 1..=3 {
                let id = format!("id=\"d1-b{b}-{view}\"");
                let start = text.find(&id).unwrap();
                let fig = &text[start..start + text[start..].find("</figure>").unwrap()];
                let (n_per_px, arrows) = force_arrows(fig);
                for (dx, dy) in arrows {
                    if view == "top" {
                        sum[0] += dx * n_per_px;
                        sum[1] -= dy * n_per_px;
                    } else {
                        sum[2] -= dy * n_per_px;
                    }
                }
            }
        }
        let fp = 20.0;
        assert!(
            sum[0].abs() < 2e-3 * fp && sum[1].abs() < 2e-3 * fp,
            "{name}: horizontal sum {sum:?}"
        );
        assert!(
            (sum[2] / fp - 1.0).abs() < 2e-3,
            "{name}: vertical sum {} N vs the preload {fp} N",
            sum[2]
        );
    }
}

/// Newtons per pixel (from the force bar and its label) and the (dx, dy)
/// pixel vectors of the force arrows of one drawing.
fn force_arrows(fig: &str) -> (f64, Vec<(f64, f64)>) {
    let num = |el: &str, k: &str| -> f64 {
        let key = format!(" {k}=\"");
        let i = el.find(&key).unwrap() + key.len();
        el[i..].split('"').next().unwrap().parse().unwrap()
    };
    let mut arrows = Vec::new();
    let mut bar = None;
    for (i, _) in fig.match_indices("<line ") {
        let el = &fig[i..i + fig[i..].find('>').unwrap()];
        if !el.contains("stroke=\"#e69f00\"") {
            continue;
        }
        let (dx, dy) = (num(el, "x2") - num(el, "x1"), num(el, "y2") - num(el, "y1"));
        if el.contains("marker-end") {
            arrows.push((dx, dy));
        } else {
            // The force bar: `<line ...><text ...>F N</text>`.
            let rest = &fig[i..];
            let t = rest.find("<text").unwrap();
            let label =
                &rest[t + rest[t..].find('>').unwrap() + 1..t + rest[t..].find("</text>").unwrap()];
            let newtons: f64 = label.trim_end_matches(" N").parse().unwrap();
            bar = Some(newtons / dx);
        }
    }
    (bar.expect("a force bar"), arrows)
}
