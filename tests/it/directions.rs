//! Named directions and frames at evaluation points (issue 39, item 3):
//! the statistics along a direction are those of the projection of the
//! sampled pose, computed here from `--out`'s samples; a frame's axes are
//! orthonormal, so the variances along them sum to those of x, y, z
//! (the trace of the covariance is invariant under a rotation); a frame
//! whose z is the coupling's z reproduces the z and phi_z columns.

use std::path::Path;

use crate::common::{kinrepro, scene};
use kinrepro::study::StudyReport;
use kinrepro::study::record::DirectionStats;

/// The README's stage with, in place of its ion beam, a direction (not
/// normalised) and a frame (z scaled, x not normal to z) at its sample
/// point.
const DIRECTIONS: &str = r#"
directions = [{ name = "beam", vector = [1.0, 0.0, 1.0] }]
frame = { name = "tool", z = [0.0, 0.0, 2.0], x = [1.0, 1.0, 0.5] }
"#;

fn stage_with(dir: &Path, extra: &str) -> String {
    let text = std::fs::read_to_string(scene("example_stage_mount.toml")).unwrap();
    let own = "directions = [{ name = \"ion beam\", vector = [0.788, 0.0, 0.616] }]";
    assert!(text.trim_end().ends_with(&format!("position = [0.0, 0.0, 0.025]\n{own}")));
    let p = dir.join("stage.toml");
    std::fs::write(&p, text.replace(own, extra)).unwrap();
    p.to_str().unwrap().to_string()
}

/// Column `name` of the samples CSV (header after the `#` line).
fn column(csv: &str, name: &str) -> Vec<f64> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap_or_else(|| panic!("{name}"));
    lines.map(|l| l.split(',').nth(k).unwrap().parse().unwrap()).collect()
}

fn sd(v: &[f64]) -> f64 {
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol * b.abs().max(1e-300), "{what}: {a} vs {b}");
}

fn direction<'a>(r: &'a StudyReport, point: &str, label: &str) -> &'a DirectionStats {
    let p = r.variants[0].points.iter().find(|p| p.name == point).unwrap();
    p.directions.iter().find(|d| d.label() == label).unwrap_or_else(|| panic!("{label}"))
}

#[test]
fn sigma_along_a_direction_is_that_of_the_projected_samples_in_every_output() {
    let dir = tempfile::tempdir().unwrap();
    let s = stage_with(dir.path(), DIRECTIONS);
    let out = dir.path().join("out");
    let html = dir.path().join("r.html");
    let (o, h) = (out.to_str().unwrap(), html.to_str().unwrap());
    let base = ["study", &s, "--sampler", "mc", "--samples", "40", "--seed", "5"];
    let (ok, json, err) =
        kinrepro(&[&base[..], &["--format", "json", "--out", o, "--html", h]].concat());
    assert!(ok, "{err}");
    let r: StudyReport = serde_json::from_str(&json).unwrap();
    let csv = std::fs::read_to_string(out.join("samples_01_stage.csv")).unwrap();
    let [x, y, z] = ["x_m", "y_m", "z_m"].map(|c| column(&csv, &format!("sample/{c}")));
    // The direction [1, 0, 1] normalised by kinrepro.
    let beam = direction(&r, "sample", "along beam");
    let h = 0.5f64.sqrt();
    let v = beam.vector.unwrap();
    (0..3).for_each(|k| close(v[k] + 1.0, [h, 0.0, h][k] + 1.0, 1e-15, "beam unit vector"));
    let projected: Vec<f64> = (0..x.len()).map(|i| h * x[i] + h * z[i]).collect();
    close(beam.sigma, 1e9 * sd(&projected), 1e-12, "sigma along beam");
    close(beam.three_sigma, 3e9 * sd(&projected), 1e-12, "3 sigma along beam");
    let max = projected.iter().cloned().fold(f64::MIN, f64::max);
    close(beam.max, 1e9 * max, 1e-12, "max along beam");
    // The recorded column is the projection (the same numbers as --out writes).
    let recorded = column(&csv, "sample/along/beam_m");
    (0..x.len()).for_each(|i| close(recorded[i], projected[i], 1e-12, "beam sample"));
    // A frame: x made normal to z, orthonormal axes.
    let fx = direction(&r, "sample", "along tool.x").vector.unwrap();
    let n = 1.0 / 2f64.sqrt();
    (0..3).for_each(|k| close(fx[k] + 1.0, [n, n, 0.0][k] + 1.0, 1e-15, "frame x axis"));
    // Trace invariance: the variances along the axes sum to x, y, z's.
    let var = |l: &str| direction(&r, "sample", l).sigma.powi(2);
    let p = &r.variants[0].points[1];
    let sum_xyz: f64 = p.sigma.values()[..3].iter().map(|s| s * s).sum();
    close(var("along tool.x") + var("along tool.y") + var("along tool.z"), sum_xyz, 1e-12, "trace");
    let sum_rot: f64 = p.sigma.values()[3..].iter().map(|s| s * s).sum();
    close(
        var("about tool.x") + var("about tool.y") + var("about tool.z"),
        sum_rot,
        1e-12,
        "trace, rotations",
    );
    close(direction(&r, "sample", "along tool.z").sigma, p.sigma.z_nm, 1e-12, "tool.z is z");
    close(
        direction(&r, "sample", "about tool.z").sigma,
        p.sigma.phi_z_nrad,
        1e-12,
        "tool.z is phi_z",
    );
    // y = z x x of the unit axes.
    let ty = [-n, n, 0.0];
    let y_proj: Vec<f64> = (0..x.len()).map(|i| ty[0] * x[i] + ty[1] * y[i]).collect();
    close(direction(&r, "sample", "along tool.y").sigma, 1e9 * sd(&y_proj), 1e-12, "tool.y");
    // The table, the HTML and the summary CSV carry the same numbers.
    let (ok, table, err) = kinrepro(&base);
    assert!(ok, "{err}");
    let row = table.lines().find(|l| l.trim_start().starts_with("along beam [nm]")).unwrap();
    assert!(row.contains(&format!("{:.3}", beam.sigma)), "{row}");
    let verdict = table.lines().find(|l| l.contains("+-3 sigma at sample")).unwrap();
    assert!(verdict.contains(&format!("along beam {:.2}", beam.three_sigma)), "{verdict}");
    let page = std::fs::read_to_string(&html).unwrap();
    let cell = format!(
        "<td class=\"l\">along beam</td><td class=\"l\">nm</td><td>{:.2}</td>",
        beam.three_sigma
    );
    assert!(page.contains(&cell), "HTML lacks {cell}");
    let (ok, summary, err) = kinrepro(&[&base[..], &["--format", "csv"]].concat());
    assert!(ok, "{err}");
    // `point,dof,unit,n,mean,min,max,sigma,...` (the scene's name before
    // them is quoted: it holds a comma).
    let header = summary.lines().find(|l| l.contains(",dof,")).unwrap();
    assert!(header.contains("point,dof,unit,n,mean,min,max,sigma,"), "{header}");
    let line = summary.lines().find(|l| l.contains(",along/beam,m,")).unwrap();
    let after = line.split_once(",along/beam,m,").unwrap().1;
    let sigma: f64 = after.split(',').nth(4).unwrap().parse().unwrap();
    close(sigma, sd(&projected), 1e-12, "summary CSV sigma");
}

#[test]
fn a_direction_a_coupling_cannot_have_is_refused_naming_its_field() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            r#"directions = [{ name = "beam", vector = [0.0, 0.0, 0.0] }]"#,
            "evaluation_points[2].directions[1].vector",
        ),
        (
            r#"directions = [{ name = "x", vector = [1.0, 0.0, 0.0] }]"#,
            "evaluation_points[2].directions[1].name",
        ),
        (
            r#"directions = [{ name = "a/b", vector = [1.0, 0.0, 0.0] }]"#,
            "evaluation_points[2].directions[1].name",
        ),
        (
            r#"directions = [{ name = "b", vector = [1.0, 0.0, 0.0] }, { name = "b", vector = [0.0, 1.0, 0.0] }]"#,
            "evaluation_points[2].directions[2].name",
        ),
        (
            r#"frame = { name = "t", z = [0.0, 0.0, 1.0], x = [0.0, 0.001, 1.0] }"#,
            "evaluation_points[2].frame.x",
        ),
        (
            r#"directions = [{ name = "beam", vector = [1.0, 0.0] }]"#,
            "evaluation_points[2].directions[1].vector",
        ),
    ];
    for (extra, field) in cases {
        let s = stage_with(dir.path(), extra);
        let (ok, _, err) = kinrepro(&["check", &s]);
        assert!(!ok, "{extra} accepted");
        assert!(err.contains(field) && err.contains("stage.toml"), "{extra}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn merged_shards_carry_the_directions() {
    let dir = tempfile::tempdir().unwrap();
    let s = stage_with(dir.path(), DIRECTIONS);
    let base =
        ["study", &s, "--sampler", "mc", "--samples", "24", "--seed", "3", "--format", "json"];
    let (ok, whole, err) = kinrepro(&base);
    assert!(ok, "{err}");
    let whole: StudyReport = serde_json::from_str(&whole).unwrap();
    let mut parts = Vec::new();
    for i in 1..=2 {
        let shard = format!("{i}/2");
        let (ok, out, err) = kinrepro(&[&base[..], &["--shard", &shard]].concat());
        assert!(ok, "{err}");
        let p = dir.path().join(format!("part{i}.json"));
        std::fs::write(&p, out).unwrap();
        parts.push(p.to_str().unwrap().to_string());
    }
    let (ok, merged, err) = kinrepro(&["merge", &parts[0], &parts[1]]);
    assert!(ok, "{err}");
    let merged: StudyReport = serde_json::from_str(&merged).unwrap();
    let (a, b) = (&whole.variants[0].points[1], &merged.variants[0].points[1]);
    assert_eq!(a.directions.len(), 7);
    for (x, y) in a.directions.iter().zip(&b.directions) {
        assert_eq!((x.label(), x.vector), (y.label(), y.vector));
        close(y.sigma, x.sigma, 1e-12, &x.label());
    }
}

#[test]
fn the_thermal_drift_along_a_direction_is_the_projection_of_the_drift() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(scene("maxwell_thermal_alu_invar.toml")).unwrap();
    let from = "position = [0.010, 0.0, -0.060]";
    assert!(text.contains(from));
    let to = format!("{from}\ndirections = [{{ name = \"radial\", vector = [3.0, 4.0, 0.0] }}]");
    let s = dir.path().join("thermal.toml");
    std::fs::write(&s, text.replace(from, &to)).unwrap();
    let out = dir.path().join("out");
    let args = ["study", s.to_str().unwrap(), "--sampler", "mc", "--samples", "12"];
    let (ok, json, err) =
        kinrepro(&[&args[..], &["--format", "json", "--out", out.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let r: StudyReport = serde_json::from_str(&json).unwrap();
    let csv = std::fs::read_to_string(out.join("samples_01_thermal.csv")).unwrap();
    let tip = r.variants[0].points.iter().find(|p| p.name == "tool tip").unwrap();
    assert!(!tip.thermal.is_empty());
    for (k, c) in tip.thermal.iter().enumerate() {
        let col = |d: &str| column(&csv, &format!("thermal/{}/tool tip/{d}", k + 1));
        let (x, y) = (col("x_m"), col("y_m"));
        let projected: Vec<f64> = (0..x.len()).map(|i| 0.6 * x[i] + 0.8 * y[i]).collect();
        let d = &c.drift.directions[0];
        assert_eq!(d.label(), "along radial");
        close(d.sigma, 1e9 * sd(&projected), 1e-12, "drift sigma along radial");
        let mean = projected.iter().sum::<f64>() / projected.len() as f64;
        close(d.mean, 1e9 * mean, 1e-12, "drift mean along radial");
    }
}

/// The README's walkthrough shows the stage's row along the ion beam as
/// `kinrepro study scenes/example_stage_mount.toml --samples 500` prints it.
#[test]
fn the_readme_row_along_the_ion_beam_reproduces() {
    let stage = scene("example_stage_mount.toml");
    let (ok, table, err) = kinrepro(&["study", stage.to_str().unwrap(), "--samples", "500"]);
    assert!(ok, "{err}");
    let row = table.lines().find(|l| l.trim_start().starts_with("along ion beam [nm]")).unwrap();
    let readme = Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md");
    let readme = std::fs::read_to_string(readme).unwrap();
    assert!(readme.contains(row.trim_end()), "README lacks the row\n{row}");
}
