//! The HTML report in a real browser (headless Chromium): it loads without a
//! console error or a blocked fetch, every drawing, table and chart is
//! present and visible (non-zero box), it fits a phone's width, and it
//! holds no external URL, script or @import. The numbers in its tables are
//! the study JSON's.
//!
//! Chromium: /usr/bin/chromium (Debian's `chromium`; .ci/run installs it).
//! Without it the browser part is skipped with a loud message, except in CI
//! (env CI=true), where that is a failure.

mod common;
#[path = "html_report/forces.rs"]
mod forces;
#[path = "html_report/study_scenes.rs"]
mod study_scenes;
#[path = "html_report/sweep.rs"]
mod sweep;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{kinrepro, scene};

/// Hooks errors, console.error and CSP violations into a list, and on load
/// writes the boxes of every `[data-check]` element into `<pre id="probe">`.
const PROBE: &str = r#"<script>
window.__errors = [];
window.addEventListener('error', e => __errors.push('error: ' + (e.message || (e.target && e.target.outerHTML || '').slice(0, 120))), true);
document.addEventListener('securitypolicyviolation', e => __errors.push('blocked: ' + e.blockedURI + ' ' + e.violatedDirective));
const __ce = console.error;
console.error = (...a) => { __errors.push('console.error: ' + a.join(' ')); __ce.apply(console, a); };
window.addEventListener('load', () => {
  const out = { errors: __errors, width: window.innerWidth, scroll_width: document.documentElement.scrollWidth, items: [] };
  document.querySelectorAll('[data-check]').forEach(el => {
    const r = el.getBoundingClientRect();
    const cs = getComputedStyle(el);
    const svg = el.querySelector('svg');
    const s = svg ? svg.getBoundingClientRect() : { width: -1, height: -1 };
    out.items.push({ kind: el.dataset.check, id: el.id, w: r.width, h: r.height,
      visible: cs.display !== 'none' && cs.visibility !== 'hidden' && cs.opacity !== '0',
      svg_w: s.width, svg_h: s.height,
      box_w: (el.closest('.scroll') || el.parentElement).clientWidth });
  });
  // Chart labels `#N` (the Pareto front's) per figure, and the SVG's box.
  out.labels = {}; out.label_svg = {};
  document.querySelectorAll('figure[data-check=chart]').forEach(f => {
    const svg = f.querySelector('svg'); if (!svg) return;
    const s = svg.getBoundingClientRect();
    out.label_svg[f.id] = [s.left, s.top, s.right, s.bottom];
    out.labels[f.id] = [...svg.querySelectorAll('text')].filter(t => /^#[0-9]+$/.test(t.textContent.trim()))
      .map(t => { const b = t.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; });
  });
  // Every text of the coupling drawings: box, font size in px of the page, dimension or not.
  out.texts = {};
  document.querySelectorAll('figure[data-check=drawing]').forEach(f => {
    const svg = f.querySelector('svg'); if (!svg) return;
    const k = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
    out.texts[f.id] = [...svg.querySelectorAll('text')].map(t => { const b = t.getBoundingClientRect();
      return { box: [b.left, b.top, b.right, b.bottom], px: parseFloat(getComputedStyle(t).fontSize) * k,
        dim: t.classList.contains('dim'), text: t.textContent }; });
  });
  const pre = document.createElement('pre');
  pre.id = 'probe';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>"#;

/// The report's CSP, and the probe's: the same, plus inline scripts.
const CSP: &str = "default-src 'none'; style-src 'unsafe-inline'; img-src data:";

fn chromium() -> Option<PathBuf> {
    let p = PathBuf::from("/usr/bin/chromium");
    if p.exists() {
        return Some(p);
    }
    if std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("CI=true but /usr/bin/chromium is missing: .ci/run installs Debian's chromium");
    }
    eprintln!(
        "\n******** SKIPPED: the browser checks of the HTML report need /usr/bin/chromium (apt-get install chromium) ********\n"
    );
    None
}

/// Run headless Chromium on `file` with a fresh profile; (stdout, stderr).
fn run_chromium(
    exe: &Path,
    tmp: &Path,
    file: &Path,
    window: &str,
    extra: &[String],
) -> (String, String) {
    let profile = tempfile::tempdir_in(tmp).unwrap();
    let out = Command::new(exe)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--enable-logging=stderr",
            "--v=0",
            "--virtual-time-budget=10000",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .arg(format!("--window-size={window}"))
        .args(extra)
        .arg(format!("file://{}", file.display()))
        .output()
        .unwrap();
    assert!(out.status.success(), "chromium failed: {}", String::from_utf8_lossy(&out.stderr));
    (
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Two studies (scenes 01 and 06 and the thermal example re-seating; the
/// tolerance scene with interchangeability) and their report with the
/// paper's reference values.
fn make_report(dir: &Path) -> (String, serde_json::Value) {
    let a = dir.join("a.json");
    let b = dir.join("b.json");
    let (s1, s6, st, th) = (
        scene("01_maxwell_vgroove_steel.toml"),
        scene("06_kelvin_steel.toml"),
        scene("tolerances_maxwell_vgroove.toml"),
        scene("maxwell_thermal_alu_invar.toml"),
    );
    let (ok, json, err) = kinrepro(&[
        "study",
        s1.to_str().unwrap(),
        s6.to_str().unwrap(),
        th.to_str().unwrap(),
        "--samples",
        "10",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    std::fs::write(&a, &json).unwrap();
    let (ok, json_b, err) = kinrepro(&[
        "study",
        st.to_str().unwrap(),
        "--samples",
        "10",
        "--vary",
        "friction,tolerances",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    std::fs::write(&b, &json_b).unwrap();
    let html = dir.join("report.html");
    let reference = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/reference/paper_table2.csv");
    let (ok, _, err) = kinrepro(&[
        "report",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--out",
        html.to_str().unwrap(),
        "--reference",
        reference.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    // Written whole; a second run refuses to overwrite.
    let (ok, _, err) = kinrepro(&["report", a.to_str().unwrap(), "--out", html.to_str().unwrap()]);
    assert!(!ok && err.contains("--force"), "{err}");
    (std::fs::read_to_string(&html).unwrap(), serde_json::from_str(&json).unwrap())
}

#[test]
fn report_is_self_contained_complete_and_renders_in_chromium() {
    let tmp = tempfile::tempdir().unwrap();
    let (html, study) = make_report(tmp.path());

    static_checks(&html, &study);
    let Some(exe) = chromium() else { return };
    browser_checks(&exe, tmp.path(), &html, &STUDY_REPORT);
}

/// Headless Chromium's DOM of `html` with the probe, at `window`.
fn probe_dom(exe: &Path, tmp: &Path, html: &str, window: &str) -> String {
    let probe_csp = format!("{CSP}; script-src 'unsafe-inline'");
    let probed = html
        .replace(&format!("content=\"{CSP}\""), &format!("content=\"{probe_csp}\""))
        .replacen("<head>", &format!("<head>\n{PROBE}"), 1);
    let probe_file = tmp.join("probe.html");
    std::fs::write(&probe_file, probed).unwrap();
    run_chromium(exe, tmp, &probe_file, window, &["--dump-dom".to_string()]).0
}

/// The probe's JSON out of a dumped DOM.
fn probe_result(dom: &str, window: &str) -> serde_json::Value {
    let start =
        dom.find("<pre id=\"probe\">").unwrap_or_else(|| panic!("{window}: the probe did not run"))
            + 16;
    let text = &dom[start..start + dom[start..].find("</pre>").unwrap()];
    let text = text.replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&");
    serde_json::from_str(&text).unwrap()
}

/// No table is wider than the box it sits in.
fn tables_fit(r: &serde_json::Value, window: &str) {
    let tables = r["items"].as_array().unwrap().iter();
    let tables: Vec<_> = tables.filter(|i| i["kind"] == "table").collect();
    assert!(!tables.is_empty());
    for t in tables {
        assert!(
            t["w"].as_f64().unwrap() <= t["box_w"].as_f64().unwrap() + 1.0,
            "{window}: a table wider than its box: {t}"
        );
    }
}

/// No external resource of any kind; the CSP; A4 print rules.
fn self_contained(html: &str) {
    let lower = html.to_lowercase();
    for bad in [
        "<script",
        "@import",
        " src=",
        "<link",
        "<iframe",
        "<img",
        "url(http",
        "href=\"http",
        "href='http",
    ] {
        assert!(!lower.contains(bad), "the report contains {bad}");
    }
    for (i, _) in lower.match_indices("href=") {
        assert!(lower[i..].starts_with("href=\"#"), "non-local link: {}", &html[i..i + 40]);
    }
    // The only http(s) strings are the SVG namespace.
    let urls = lower.matches("http://").count() + lower.matches("https://").count();
    assert_eq!(urls, lower.matches("xmlns=\"http://www.w3.org/2000/svg\"").count());
    assert!(html.contains(&format!("content=\"{CSP}\"")));
    assert!(html.contains("@media print") && html.contains("size: A4"));
}

/// No external resource; metadata, scenes, references and the JSON's
/// numbers present; every chart and drawing there.
fn static_checks(html: &str, study: &serde_json::Value) {
    self_contained(html);

    // Metadata, both scene forms, reference rows, the JSON's numbers.
    for s in [
        "solver",
        "quasi-static",
        "sampler",
        "seed",
        "samples",
        "kinrepro version",
        "Explicit form of",
        "[coupling]",
        "[[balls]]",
        "reference: paper (FE, 25 LHS)",
        "σ_φz [nrad]",
    ] {
        assert!(html.contains(s), "missing {s}");
    }
    for v in study["variants"].as_array().unwrap() {
        for p in v["points"].as_array().unwrap() {
            let sx = p["sigma"]["x_nm"].as_f64().unwrap();
            let lo = p["sigma_ci90_low"]["phi_z_nrad"].as_f64().unwrap();
            assert!(html.contains(&format!("<td>{sx:.3}<span")), "sigma_x {sx:.3} not in a table");
            assert!(html.contains(&format!("[{lo:.2},")), "interval {lo:.2} not in a table");
        }
    }
    // The verdict first: +-3 sigma of every point with 3 times sigma's
    // interval, and the friction-limit warning of the paper's scene 01
    // (mu0 + spread = 0.55 above its limit 0.3066, as `check` says).
    let verdict = html.find("<section id=\"verdict\">").expect("a verdict section");
    assert!(verdict < html.find("<section id=\"run\">").unwrap(), "the verdict opens the report");
    for v in study["variants"].as_array().unwrap() {
        for p in v["points"].as_array().unwrap() {
            let three = p["three_sigma"]["x_nm"].as_f64().unwrap();
            let lo = 3.0 * p["sigma_ci90_low"]["x_nm"].as_f64().unwrap();
            assert!(html.contains(&format!("<td>{three:.3}<span")), "+-3 sigma_x {three:.3}");
            assert!(html.contains(&format!("[{lo:.2},")), "its interval from {lo:.2}");
        }
    }
    let a = &study["variants"][0]["assessment"];
    assert_eq!(a["above_friction_limit"], true, "{a}");
    let limit = a["friction_limit"].as_f64().unwrap();
    assert!(
        html.contains(&format!("above the friction limit for seating {limit:.4}"))
            && html.contains("<li class=\"warn\">"),
        "the friction-limit warning"
    );
    // The thermal example's drift: its table (each cycle point's mean z of
    // the centre) and its plot.
    let thermal = &study["variants"][2]["points"][0]["thermal"];
    for c in thermal.as_array().unwrap() {
        let z = c["mean"]["z_nm"].as_f64().unwrap();
        assert!(html.contains(&format!("<td>{z:.3}")), "drift mean z {z:.3} not in a table");
    }
    assert!(
        html.contains("Thermal drift along the [thermal] cycle") && html.contains("thermal-drift")
    );
    // 12 charts (bars, interchange bars, scatter, convergence, thermal drift,
    // interchange scatter, and a histogram per re-seating point: 1 + 2 + 2
    // + 1); per scene a layout and a top and a side view of each of 3 balls.
    assert_eq!(html.matches("data-check=\"chart\"").count(), 12);
    assert_eq!(html.matches("data-check=\"drawing\"").count(), 4 * 7);
}

/// In Chromium: a screenshot without console errors, the probe at desktop
/// and phone widths, and A4 print.
/// What a report holds: charts, drawings, at least so many tables, scenes.
struct Expect {
    charts: usize,
    drawings: usize,
    min_tables: usize,
    scenes: usize,
}

/// The study report of `make_report`.
const STUDY_REPORT: Expect = Expect { charts: 12, drawings: 28, min_tables: 9, scenes: 8 };

fn browser_checks(exe: &Path, tmp: &Path, html: &str, expect: &Expect) {
    let file = tmp.join("report.html");
    // 1. The report itself: a screenshot, no console error, nothing blocked.
    let shot = tmp.join("shot.png");
    let (_, log) =
        run_chromium(exe, tmp, &file, "1280,2000", &[format!("--screenshot={}", shot.display())]);
    let png = std::fs::read(&shot).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    let (w, h) = (
        u32::from_be_bytes(png[16..20].try_into().unwrap()),
        u32::from_be_bytes(png[20..24].try_into().unwrap()),
    );
    assert_eq!((w, h), (1280, 2000));
    for line in log.lines() {
        let l = line.to_lowercase();
        assert!(
            !(l.contains("console")
                && (l.contains("error") || l.contains("uncaught") || l.contains("refused")))
                && !l.contains("content security policy"),
            "browser console: {line}"
        );
    }
    // 2. With the probe, on a desktop and on a phone width.
    // Desktop, and the narrowest window headless Chromium opens (500 px).
    for window in ["1280,2000", "500,900"] {
        let dom = probe_dom(exe, tmp, html, window);
        check_probe(&dom, window, expect);
    }
}

fn check_probe(dom: &str, window: &str, expect: &Expect) {
    let r = probe_result(dom, window);
    assert_eq!(r["errors"].as_array().unwrap().len(), 0, "{window}: {}", r["errors"]);
    let width = r["width"].as_f64().unwrap();
    assert!(
        r["scroll_width"].as_f64().unwrap() <= width + 1.0,
        "{window}: the page is wider than the window: {r}"
    );
    let items = r["items"].as_array().unwrap();
    let count = |k: &str| items.iter().filter(|i| i["kind"] == k).count();
    assert_eq!(count("chart"), expect.charts, "{window}");
    assert_eq!(count("drawing"), expect.drawings, "{window}");
    assert!(
        count("table") >= expect.min_tables && count("scene") == expect.scenes,
        "{window}: {}",
        count("table")
    );
    for i in items {
        let what = format!("{window}: {} {}", i["kind"], i["id"]);
        assert_eq!(i["visible"], true, "{what}");
        assert!(i["w"].as_f64().unwrap() > 10.0 && i["h"].as_f64().unwrap() > 10.0, "{what}: {i}");
        // Tables may be wider: they scroll inside their box (the page's
        // scroll width above covers that box).
        assert!(
            i["kind"] == "table" || i["w"].as_f64().unwrap() <= width + 1.0,
            "{what} wider than the window: {i}"
        );
        if i["kind"] == "chart" || i["kind"] == "drawing" {
            assert!(
                i["svg_w"].as_f64().unwrap() > 10.0 && i["svg_h"].as_f64().unwrap() > 10.0,
                "{what}: {i}"
            );
        }
    }
}

/// `study --html` writes the report of the run; `report` refuses a shard
/// part, a scene file changed since the study, and a bad reference row,
/// each with one line naming the file and the reason, and writes nothing.
#[test]
fn study_html_and_bad_inputs() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let sc = dir.join("01_copy.toml");
    std::fs::copy(scene("01_maxwell_vgroove_steel.toml"), &sc).unwrap();
    let html = dir.join("run.html");
    let (ok, _, err) = kinrepro(&[
        "study",
        sc.to_str().unwrap(),
        "--samples",
        "10",
        "--html",
        html.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&html).unwrap();
    // Bars, scatter, convergence and the centre's histogram.
    assert_eq!(text.matches("data-check=\"chart\"").count(), 4);
    assert_eq!(text.matches("data-check=\"drawing\"").count(), 7);
    assert!(text.contains("this run") && text.contains("01_copy.toml"));

    let json = dir.join("s.json");
    let (ok, out, err) =
        kinrepro(&["study", sc.to_str().unwrap(), "--samples", "10", "--format", "json"]);
    assert!(ok, "{err}");
    std::fs::write(&json, out).unwrap();
    let target = dir.join("r.html");
    let report = |args: &[&str]| {
        let mut a = vec!["report", json.to_str().unwrap(), "--out", target.to_str().unwrap()];
        a.extend_from_slice(args);
        kinrepro(&a)
    };
    // A bad reference row: file, line, column.
    let reference = dir.join("ref.csv");
    std::fs::write(&reference, "label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\np,01_copy,centre,1,2,abc,,,\n").unwrap();
    let (ok, _, err) = report(&["--reference", reference.to_str().unwrap()]);
    assert!(!ok && err.contains("ref.csv:2: z_nm") && err.lines().count() == 1, "{err}");
    assert!(!target.exists());
    // The scene changed since the study: refused.
    let edited = std::fs::read_to_string(&sc).unwrap().replace("force = 20.0", "force = 25.0");
    std::fs::write(&sc, edited).unwrap();
    let (ok, _, err) = report(&[]);
    assert!(!ok && err.contains("changed since the study"), "{err}");
    assert!(!target.exists());
    // A shard part: refused (merge first).
    let (ok, out, err) = kinrepro(&[
        "study",
        scene("01_maxwell_vgroove_steel.toml").to_str().unwrap(),
        "--samples",
        "10",
        "--shard",
        "1/2",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    std::fs::write(&json, out).unwrap();
    let (ok, _, err) = report(&[]);
    assert!(!ok && err.contains("merge the parts first"), "{err}");
    assert!(!target.exists());
}
