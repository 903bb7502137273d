//! The plots are written as SVG with real <text> labels carrying units.

use std::path::PathBuf;

use kinrepro::study::StudyError;
use kinrepro::study::plot::{
    ConvergenceSeries, Dof, VariantScatter, VariantSigma, plot_convergence, plot_sigma_bars,
    plot_xy_scatter,
};
use kinrepro::study::stats::sigma_convergence;

fn out(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("plots");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn read_svg(path: &PathBuf) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(!text.is_empty());
    assert!(text.contains("<svg"));
    assert!(text.contains("<text"));
    text
}

fn variants() -> Vec<VariantSigma> {
    vec![
        VariantSigma {
            variant: "three-groove".into(),
            sigma: [12.0, 9.5, 3.1, 40.0, 35.0, 20.0],
        },
        VariantSigma {
            variant: "tetrahedron-groove-flat".into(),
            sigma: [20.0, 14.0, 5.0, 55.0, 61.0, 30.0],
        },
        VariantSigma {
            variant: "coated".into(),
            sigma: [4.0, 3.0, 1.0, 12.0, 10.0, 5.0],
        },
    ]
}

#[test]
fn sigma_bars_svg_has_units_and_names() {
    let path = out("sigma_bars.svg");
    plot_sigma_bars(&path, &variants()).unwrap();
    let svg = read_svg(&path);
    for label in [
        "σ [nm]",
        "σ [nrad]",
        "degree of freedom",
        "three-groove",
        "coated",
        "\nφx\n",
        "\nz\n",
    ] {
        assert!(svg.contains(label), "missing {label}");
    }
}

#[test]
fn scatter_svg_has_axis_labels() {
    let path = out("xy_scatter.svg");
    let data: Vec<VariantScatter> = variants()
        .iter()
        .enumerate()
        .map(|(v, s)| VariantScatter {
            variant: s.variant.clone(),
            xy: (0..25)
                .map(|i| {
                    let t = f64::from(i) * 0.9 + v as f64;
                    (s.sigma[0] * t.sin(), s.sigma[1] * (1.7 * t).cos())
                })
                .collect(),
        })
        .collect();
    plot_xy_scatter(&path, &data).unwrap();
    let svg = read_svg(&path);
    assert!(svg.contains("x [nm]") && svg.contains("y [nm]"));
    assert!(svg.contains("three-groove (25 samples)"));
    assert!(svg.matches("<circle").count() >= 75);
}

#[test]
fn convergence_svg_has_both_units() {
    let path = out("convergence.svg");
    let series: Vec<ConvergenceSeries> = [(Dof::X, 1.0), (Dof::Y, 2.0), (Dof::PhiX, 10.0)]
        .iter()
        .map(|&(dof, scale)| {
            let x: Vec<f64> = (0..25)
                .map(|i| scale * (f64::from(i) * 2.1).sin())
                .collect();
            ConvergenceSeries {
                variant: "three-groove".into(),
                dof,
                points: sigma_convergence(&x).unwrap(),
            }
        })
        .collect();
    plot_convergence(&path, &series).unwrap();
    let svg = read_svg(&path);
    assert!(svg.contains("number of samples k"));
    assert!(svg.contains("σ of first k samples [nm]"));
    assert!(svg.contains("σ of first k samples [nrad]"));
}

#[test]
fn bad_plot_inputs_are_errors() {
    assert!(matches!(
        plot_sigma_bars(&out("e1.svg"), &[]),
        Err(StudyError::NothingToPlot(_))
    ));
    let mut v = variants();
    v[0].sigma[2] = f64::NAN;
    assert!(matches!(
        plot_sigma_bars(&out("e2.svg"), &v),
        Err(StudyError::NonFinite { .. })
    ));
    assert!(plot_xy_scatter(&out("e3.svg"), &[]).is_err());
    assert!(plot_convergence(&out("e4.svg"), &[]).is_err());
    let mut huge = variants();
    huge[1].sigma[0] = 1.7e308;
    assert!(matches!(
        plot_sigma_bars(&out("e5.svg"), &huge),
        Err(StudyError::NonFinite { .. })
    ));
    let bad_dir = out("no_such_dir").join("x.svg");
    assert!(matches!(
        plot_sigma_bars(&bad_dir, &variants()),
        Err(StudyError::Plot(_))
    ));
}
