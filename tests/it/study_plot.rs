//! The plots are SVG with real <text> labels carrying units; the sigma bars
//! carry the interval of each sigma and the reference values at the right
//! height; the scatter names every evaluation point; the convergence plot
//! has all six DOFs; the interchangeability is plotted when tolerances vary.

use crate::common;

use kinrepro::dof::Dof;
use kinrepro::report::study::charts::study_charts;
use kinrepro::report::study::plot::{
    ConvergenceSeries, PlotError, VariantScatter, VariantSigma, convergence_svg, histogram,
    normal_count, sigma_bars_svg, xy_scatter_svg,
};
use kinrepro::study::stats::sigma_convergence;
use kinrepro::study::{Sampler, StudyOptions, VariantReport, Varied};

fn variants() -> Vec<VariantSigma> {
    vec![
        VariantSigma::new("three-groove", [12.0, 9.5, 3.1, 40.0, 35.0, 20.0]),
        VariantSigma::new("tetrahedron-groove-flat", [20.0, 14.0, 5.0, 55.0, 61.0, 30.0]),
        VariantSigma::new("coated", [4.0, 3.0, 1.0, 12.0, 10.0, 5.0]),
    ]
}

/// Numeric attribute `name` of an SVG element's text.
fn attr(el: &str, name: &str) -> Option<f64> {
    let el = format!(" {el}");
    let key = format!(" {name}=\"");
    let i = el.find(&key)? + key.len();
    el[i..].split('"').next()?.parse().ok()
}

/// The elements `<tag ...>` of an SVG.
fn elements<'a>(svg: &'a str, tag: &str) -> Vec<&'a str> {
    svg.split(&format!("<{tag} ")).skip(1).map(|s| s.split('>').next().unwrap_or("")).collect()
}

/// The point list of a polyline element.
fn points(el: &str) -> Vec<(f64, f64)> {
    let i = el.find("points=\"").unwrap() + 8;
    el[i..]
        .split('"')
        .next()
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

#[test]
fn sigma_bars_svg_has_units_and_names() {
    let svg = sigma_bars_svg(&variants(), "re-seating σ").unwrap();
    assert!(svg.contains("<svg") && svg.contains("<text"));
    for label in [
        "σ [nm]",
        "σ [nrad]",
        "degree of freedom",
        "three-groove",
        "coated",
        "\nφx\n",
        "\nφz\n",
        "\nz\n",
    ] {
        assert!(svg.contains(label), "missing {label}");
    }
}

/// The error bar of each sigma spans [low, high] on the bar's own axis: with
/// the bar drawn from pixel y0 (sigma 0) to y_s (sigma s), a value v sits at
/// y0 - (y0 - y_s) v / s. Reference ticks sit at their value likewise.
#[test]
fn sigma_bars_draw_intervals_and_references_at_their_values() {
    let mut data = variants();
    let sigma = data[0].sigma;
    let lo = sigma.map(|s| 0.7 * s);
    let hi = sigma.map(|s| 1.4 * s);
    data[0].interval = Some((lo, hi));
    data[1].interval = Some((data[1].sigma.map(|s| 0.9 * s), data[1].sigma.map(|s| 1.1 * s)));
    data[0].reference = Some([Some(15.0), None, Some(2.0), Some(50.0), None, None]);
    let svg = sigma_bars_svg(&data, "re-seating σ").unwrap();
    assert!(svg.contains("reference value (tick); 90 % interval (bar)"));
    // Bars of variant 0 (first colour), in drawing order x, y, z | phi_x, phi_y, phi_z.
    let bars: Vec<(f64, f64, f64, f64)> = elements(&svg, "rect")
        .into_iter()
        .filter(|r| r.contains("fill=\"#0072B2\"") && attr(r, "width").is_some_and(|w| w < 100.0))
        .map(|r| {
            let (x, y, w, h) = (
                attr(r, "x").unwrap(),
                attr(r, "y").unwrap(),
                attr(r, "width").unwrap(),
                attr(r, "height").unwrap(),
            );
            (x, w, y + h, y)
        })
        .collect();
    // The bars stand on the x axis (the lowest bottom); the legend's sample
    // rectangle does not.
    let axis = bars.iter().map(|b| b.2).fold(0.0, f64::max);
    let bars: Vec<_> = bars.into_iter().filter(|b| b.2 == axis).collect();
    assert_eq!(bars.len(), 6, "six bars of variant 0");
    let lines = elements(&svg, "polyline");
    let error_bars: Vec<Vec<(f64, f64)>> = lines
        .iter()
        .filter(|l| l.contains("stroke=\"#000000\" stroke-width=\"2\""))
        .map(|l| points(l))
        .filter(|p| p.len() == 2 && p[0].0 == p[1].0)
        .collect();
    assert_eq!(error_bars.len(), 12, "one error bar per DOF of both variants with intervals");
    let ticks: Vec<Vec<(f64, f64)>> = lines
        .iter()
        .filter(|l| l.contains("stroke=\"#000000\" stroke-width=\"4\""))
        .map(|l| points(l))
        .collect();
    // Three reference values, plus the legend's sample tick.
    assert_eq!(ticks.len(), 4);
    let at = |bar: (f64, f64, f64, f64), v: f64, s: f64| bar.2 - (bar.2 - bar.3) * v / s;
    for (k, &bar) in bars.iter().enumerate() {
        let e = error_bars
            .iter()
            .find(|p| p[0].0 >= bar.0 && p[0].0 <= bar.0 + bar.1)
            .unwrap_or_else(|| panic!("no error bar over bar {k}"));
        let (top, bottom) = (e[0].1.min(e[1].1), e[0].1.max(e[1].1));
        assert!((bottom - at(bar, lo[k], sigma[k])).abs() < 1.6, "dof {k}: low end {bottom}");
        assert!((top - at(bar, hi[k], sigma[k])).abs() < 1.6, "dof {k}: high end {top}");
        let reference = data[0].reference.unwrap()[k];
        let tick = ticks.iter().find(|p| p[0].0 >= bar.0 - 0.5 && p[1].0 <= bar.0 + bar.1 + 0.5);
        match (reference, tick) {
            (Some(v), Some(t)) => assert!((t[0].1 - at(bar, v, sigma[k])).abs() < 1.6),
            (None, None) => {}
            (r, t) => panic!("dof {k}: reference {r:?} but tick {t:?}"),
        }
    }
}

#[test]
fn bad_plot_inputs_are_errors() {
    assert!(matches!(sigma_bars_svg(&[], "σ"), Err(PlotError::NothingToPlot(_))));
    let mut v = variants();
    v[0].sigma[2] = f64::NAN;
    assert!(matches!(sigma_bars_svg(&v, "σ"), Err(PlotError::NonFinite { .. })));
    let mut v = variants();
    v[1].interval = Some(([1.0; 6], [f64::INFINITY; 6]));
    assert!(matches!(sigma_bars_svg(&v, "σ"), Err(PlotError::NonFinite { .. })));
    assert!(xy_scatter_svg(&[]).is_err());
    assert!(convergence_svg(&[]).is_err());
    let mut huge = variants();
    huge[1].sigma[0] = 1.7e308;
    assert!(matches!(sigma_bars_svg(&huge, "σ"), Err(PlotError::NonFinite { .. })));
    let scatter =
        VariantScatter { variant: "a".into(), point: "centre".into(), xy: vec![(f64::NAN, 0.0)] };
    assert!(xy_scatter_svg(&[scatter]).is_err());
}

/// A study of `scene` with `samples` Monte Carlo samples (sigma: the plain
/// sample standard deviation), as its report.
fn study(scene: &str, samples: usize, vary: Vec<Varied>) -> VariantReport {
    let c = common::load(scene);
    let opts = StudyOptions {
        samples: Some(samples),
        sampler: Some(Sampler::MonteCarlo),
        vary,
        ..Default::default()
    };
    common::report(&common::plan(vec![c], &opts))
}

/// The Kelvin clamp has two evaluation points: the scatter has a named
/// panel with every sample for each; the convergence plot has one panel per
/// DOF (all six), one line per variant and point, each ending at the sigma
/// of all samples (computed here from the records, two-pass).
#[test]
fn scatter_names_every_point_and_convergence_has_six_dofs() {
    let n = 10;
    let v = study("06_kelvin_steel.toml", n, vec![Varied::Friction]);
    let charts = study_charts(&[&v], &[]).unwrap();
    let names: Vec<&str> = charts.iter().map(|c| c.file_name.as_str()).collect();
    let expected = ["sigma_bars.svg", "scatter_xy.svg", "sigma_convergence.svg"];
    assert_eq!(names, [&expected[..], &["histogram_1_1.svg", "histogram_1_2.svg"]].concat());
    let scatter = &charts[1].svg;
    for point in ["centre", "trihedral ball"] {
        let caption = format!("06_kelvin_steel · {point} ({n} samples)");
        assert!(scatter.contains(&caption), "missing {caption}");
    }
    assert_eq!(elements(scatter, "circle").len(), 2 * n);
    let conv = &charts[2].svg;
    for (dof, unit) in
        [("x", "nm"), ("y", "nm"), ("z", "nm"), ("φx", "nrad"), ("φy", "nrad"), ("φz", "nrad")]
    {
        let caption = format!("convergence of σ {dof} [{unit}]");
        assert!(conv.contains(&caption), "missing {caption}");
    }
    assert!(conv.contains("06_kelvin_steel · trihedral ball"));
    // Series: 2 points x 6 DOFs; the last value of each is the sigma of all samples.
    let k_of = |dof: usize, point: usize| -> f64 {
        let values: Vec<f64> = v.records.iter().map(|r| r.outputs[6 * point + dof] * 1e9).collect();
        let last = sigma_convergence(&values).unwrap().last().unwrap().sigma;
        let mean = values.iter().sum::<f64>() / n as f64;
        let s = (values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
        assert!((last / s - 1.0).abs() < 1e-9, "{last} vs {s}");
        s
    };
    for point in 0..2 {
        for dof in 0..6 {
            let s = k_of(dof, point);
            let table = &v.points[point].sigma.values()[dof];
            assert!((s / table - 1.0).abs() < 1e-9, "plotted series ends at the table's sigma");
        }
    }
}

#[test]
fn convergence_svg_has_a_panel_per_dof_given() {
    let series: Vec<ConvergenceSeries> = [(Dof::X, 1.0), (Dof::PhiZ, 10.0)]
        .iter()
        .map(|&(dof, scale)| {
            let x: Vec<f64> = (0..25).map(|i| scale * (f64::from(i) * 2.1).sin()).collect();
            ConvergenceSeries {
                variant: "three-groove".into(),
                dof,
                points: sigma_convergence(&x).unwrap(),
            }
        })
        .collect();
    let svg = convergence_svg(&series).unwrap();
    assert!(svg.contains("convergence of σ x [nm]") && svg.contains("convergence of σ φz [nrad]"));
    assert!(!svg.contains("convergence of σ y"));
    assert!(svg.contains("number of samples k"));
}

/// Interchangeability bars and scatter appear exactly when tolerances vary.
#[test]
fn interchangeability_is_plotted_when_tolerances_vary() {
    let tol = vec![Varied::Friction, Varied::Tolerances];
    let v = study("tolerances_maxwell_vgroove.toml", 8, tol);
    let charts = study_charts(&[&v], &[]).unwrap();
    let names: Vec<&str> = charts.iter().map(|c| c.file_name.as_str()).collect();
    assert!(names.contains(&"interchange_sigma_bars.svg"), "{names:?}");
    assert!(names.contains(&"interchange_scatter_xy.svg"), "{names:?}");
    let bars = &charts.iter().find(|c| c.file_name == "interchange_sigma_bars.svg").unwrap().svg;
    assert!(bars.contains("interchange σ, translations"));
    let plain = study("tolerances_maxwell_vgroove.toml", 8, vec![Varied::Friction]);
    let charts = study_charts(&[&plain], &[]).unwrap();
    assert!(charts.iter().all(|c| !c.file_name.starts_with("interchange")));
}

/// `--sensitivity` reaches the charts and the report (issue 39): one chart
/// per block, each DOF's panel with the variance share, S and ST of every
/// input as bars whose heights are proportional to the JSON's values (the
/// share bars of the x panel here), the Sobol bars with interval bars, and
/// the chart in the HTML report.
#[test]
fn sensitivity_chart_bars_carry_the_json_values() {
    let s01 = common::scene("01_maxwell_vgroove_steel.toml").display().to_string();
    let dir = tempfile::tempdir().unwrap();
    let (out, html) = (dir.path().join("out"), dir.path().join("r.html"));
    let base = ["study", &s01, "--samples", "60", "--sensitivity", "--sobol-samples", "64"];
    let (ok, json, err) = common::kinrepro(&[&base[..], &["--format", "json"]].concat());
    assert!(ok, "{err}");
    let files = ["--out", out.to_str().unwrap(), "--html", html.to_str().unwrap()];
    let (ok, _, err) = common::kinrepro(&[&base[..], &files[..]].concat());
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let block = &v["variants"][0]["sensitivity"][0];
    let share: Vec<f64> =
        block["dofs"][0]["share"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    let svg = std::fs::read_to_string(out.join("sensitivity_1_reseating.svg")).unwrap();
    for label in ["variance share (SRC²)", "Sobol S (first order)", "Sobol ST (total)", "mu_6"] {
        assert!(svg.contains(label), "{label}");
    }
    // The share bars (the first colour) of the top row stand on one
    // baseline; sorted by x, the first six are the x panel's.
    let mut bars: Vec<(f64, f64, f64)> = elements(&svg, "rect")
        .into_iter()
        .filter(|r| r.contains("fill=\"#0072B2\"") && attr(r, "width").is_some_and(|w| w < 60.0))
        .filter_map(|r| {
            Some((attr(r, "x")?, attr(r, "y")? + attr(r, "height")?, attr(r, "height")?))
        })
        .collect();
    // (The legend's swatch, in the 44 px title band, is not a bar.)
    bars.retain(|b| b.1 > 44.0);
    let top = bars.iter().map(|b| b.1).fold(f64::INFINITY, f64::min);
    bars.retain(|b| (b.1 - top).abs() < 1.0 && b.2 > 0.0);
    bars.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap());
    let (k, _) =
        share.iter().enumerate().fold((0, 0.0), |a, (j, &s)| if s > a.1 { (j, s) } else { a });
    let scale = bars[k].2 / share[k];
    for (j, s) in share.iter().enumerate().filter(|(_, s)| **s * scale > 1.0) {
        let h = bars.iter().take(6).nth(j).map_or(0.0, |b| b.2);
        assert!(
            (h - s * scale).abs() < 1.5,
            "input {j}: bar {h} px, share {s} -> {} px",
            s * scale
        );
    }
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains("id=\"sensitivity-1-reseating\"") && page.contains("Sobol ST (total)"));
}

/// Standard normal pairs by Box-Muller from a ChaCha stream.
fn normals(n: usize, seed: u64) -> Vec<(f64, f64)> {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|_| {
            let (u1, u2): (f64, f64) = (1.0 - rng.random::<f64>(), rng.random());
            let r = (-2.0 * u1.ln()).sqrt();
            let t = std::f64::consts::TAU * u2;
            (r * t.cos(), r * t.sin())
        })
        .collect()
}

/// The scatter's ellipse: every point on m + sqrt(c) L u with c the 90 %
/// quantile of chi-square with 2 degrees of freedom, -2 ln 0.1 (its
/// Mahalanobis radius by the sample covariance, computed here), and it
/// holds 90 % of fresh draws of the same correlated normal (within 3
/// standard errors of a binomial proportion).
#[test]
fn the_scatter_ellipse_holds_90_percent_of_a_normal() {
    use kinrepro::report::study::plot::covariance_ellipse;
    // x = 3 z1, y = 1.2 z1 + 2 z2: correlated, not axis-aligned.
    let correlated = |z: &[(f64, f64)]| -> Vec<(f64, f64)> {
        z.iter().map(|&(a, b)| (10.0 + 3.0 * a, -4.0 + 1.2 * a + 2.0 * b)).collect()
    };
    let xy = correlated(&normals(4000, 11));
    let e = covariance_ellipse(&xy, 0.90).unwrap();
    let n = xy.len() as f64;
    let (mx, my) = xy.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    let s = |f: &dyn Fn(f64, f64) -> f64| {
        xy.iter().map(|&(x, y)| f(x - mx, y - my)).sum::<f64>() / (n - 1.0)
    };
    let (sxx, sxy, syy) = (s(&|a, _| a * a), s(&|a, b| a * b), s(&|_, b| b * b));
    let det = sxx * syy - sxy * sxy;
    let mahalanobis = |x: f64, y: f64| {
        let (dx, dy) = (x - mx, y - my);
        (syy * dx * dx - 2.0 * sxy * dx * dy + sxx * dy * dy) / det
    };
    let c = -2.0 * 0.1f64.ln();
    for &(x, y) in &e {
        assert!((mahalanobis(x, y) / c - 1.0).abs() < 1e-9, "({x}, {y})");
    }
    let fresh = correlated(&normals(20_000, 12));
    let inside = fresh.iter().filter(|&&(x, y)| mahalanobis(x, y) <= c).count() as f64;
    let share = inside / fresh.len() as f64;
    let se = (0.9 * 0.1 / fresh.len() as f64).sqrt();
    assert!((share - 0.9).abs() < 3.0 * se + 0.01, "{share}");
}

/// Tick labels of the x axis never overlap: in a 16-panel scatter (the
/// narrowest panels) each label's estimated width (0.6 em per character)
/// leaves a gap to its neighbour in the same row.
#[test]
fn scatter_tick_labels_do_not_overlap() {
    let xy = normals(50, 3).iter().map(|&(a, b)| (25.0 * a, 25.0 * b)).collect::<Vec<_>>();
    let data: Vec<VariantScatter> = (0..16)
        .map(|i| VariantScatter {
            variant: format!("v{i}"),
            point: "centre".into(),
            xy: xy.clone(),
        })
        .collect();
    let svg = xy_scatter_svg(&data).unwrap();
    // (x, y, width) of each numeric label written centred (the x ticks).
    let mut labels: Vec<(f64, f64, f64)> = Vec::new();
    for chunk in svg.split("<text ").skip(1) {
        let (head, rest) = chunk.split_once('>').unwrap();
        let text = rest.split("</text>").next().unwrap().trim();
        if !head.contains("text-anchor=\"middle\"") || text.parse::<f64>().is_err() {
            continue;
        }
        let size = attr(head, "font-size").unwrap();
        labels.push((
            attr(head, "x").unwrap(),
            attr(head, "y").unwrap(),
            0.6 * size * text.len() as f64,
        ));
    }
    assert!(labels.len() >= 16 * 3, "{} x tick labels", labels.len());
    labels.sort_by(|a, b| (a.1, a.0).partial_cmp(&(b.1, b.0)).unwrap());
    for w in labels.windows(2) {
        let (a, b) = (w[0], w[1]);
        if a.1 == b.1 {
            assert!(b.0 - a.0 > (a.2 + b.2) / 2.0 + 2.0, "labels at {a:?} and {b:?} overlap");
        }
    }
}

/// One colour per series on a page: the i-th series (variant, then
/// evaluation point) has the same colour in the sigma bars and in the
/// scatter panels (scene 06 has two points, so three series with scene 01;
/// the scatter once coloured by variant and gave two).
#[test]
fn a_series_has_one_colour_in_bars_and_scatter() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let (s06, s01) =
        (common::scene("06_kelvin_steel.toml"), common::scene("01_maxwell_vgroove_steel.toml"));
    let args = [
        "study",
        s06.to_str().unwrap(),
        s01.to_str().unwrap(),
        "--samples",
        "20",
        "--out",
        out.to_str().unwrap(),
    ];
    let (ok, _, err) = common::kinrepro(&args);
    assert!(ok, "{err}");
    let fills = |file: &str, tag: &str, keep: &dyn Fn(&str) -> bool| -> Vec<String> {
        let svg = std::fs::read_to_string(out.join(file)).unwrap();
        let mut seen: Vec<String> = Vec::new();
        for el in elements(&svg, tag).into_iter().filter(|e| keep(e)) {
            let Some(i) = el.find("fill=\"#") else { continue };
            let f = el[i + 6..i + 13].to_string();
            if f != "#FFFFFF" && f != "#000000" && !seen.contains(&f) {
                seen.push(f);
            }
        }
        seen
    };
    let bars = fills("sigma_bars.svg", "rect", &|r| attr(r, "width").is_some_and(|w| w < 100.0));
    let dots = fills("scatter_xy.svg", "circle", &|_| true);
    assert_eq!(dots.len(), 3, "{dots:?}");
    assert_eq!(bars[..3], dots[..], "bars {bars:?}, scatter {dots:?}");
    // Each point's histogram has its series' colour.
    for (file, dot) in
        ["histogram_1_1.svg", "histogram_1_2.svg", "histogram_2_1.svg"].iter().zip(&dots)
    {
        let hist = fills(file, "rect", &|r| r.contains("opacity=\"0.7\""));
        assert_eq!(hist, std::slice::from_ref(dot), "{file}");
    }
}

/// Histograms: every sample is counted once, in the bin that holds it; the
/// curve is the normal of the reported mean and sigma as expected counts
/// (its sum over bins of a fine grid is n); the chart draws one bar per
/// non-empty bin of each of the six panels, at the bin's count.
#[test]
fn histograms_count_every_sample_and_draw_the_normal_of_the_reported_sigma() {
    let n = 40;
    let v = study("01_maxwell_vgroove_steel.toml", n, vec![Varied::Friction]);
    let charts = study_charts(&[&v], &[]).unwrap();
    let chart = charts.iter().find(|c| c.file_name == "histogram_1_1.svg").unwrap();
    let mut nonempty = 0;
    for (k, dof) in Dof::ALL.iter().enumerate() {
        let values: Vec<f64> = v.records.iter().map(|r| r.outputs[k] * 1e9).collect();
        let (edges, counts) = histogram(&values).unwrap();
        assert_eq!(counts.iter().sum::<usize>(), n);
        assert_eq!(edges.len(), counts.len() + 1);
        for x in &values {
            let inside =
                (0..counts.len()).filter(|&b| edges[b] <= *x && *x <= edges[b + 1]).count();
            assert!(inside >= 1, "{x} in no bin");
        }
        nonempty += counts.iter().filter(|&&c| c > 0).count();
        let label = format!("{} [{}]", dof.name(), dof.unit());
        assert!(chart.svg.contains(&label), "missing {label}");
        // The expected counts of a normal sum to n over a fine grid.
        let (m, s) = (v.points[0].mean.values()[k], v.points[0].sigma.values()[k]);
        let w = s / 100.0;
        let total: f64 =
            (-1000..1000).map(|i| normal_count(m + (i as f64 + 0.5) * w, n, w, m, s)).sum();
        assert!((total / n as f64 - 1.0).abs() < 1e-9, "{total}");
    }
    let bars = elements(&chart.svg, "rect").into_iter().filter(|r| r.contains("opacity=\"0.7\""));
    assert_eq!(bars.filter(|r| attr(r, "height").is_some_and(|h| h > 0.0)).count(), nonempty);
}
