//! `kinrepro check` and `kinrepro expand`: scene validation.

use crate::args::*;

pub fn check(args: CheckArgs) -> Result<(), String> {
    let CheckArgs { scenes } = args;
    let mut failed = 0;
    for path in &scenes {
        match kinrepro::error::load_coupling(path) {
            Ok(c) => {
                let moves = kinrepro::study::runner::friction_moves_pose(&c, &Default::default())
                    .map_err(|e| e.to_string())?;
                let note = kinrepro::report::check::seating_note(&c, moves);
                let summary = kinrepro::report::check::check_summary(&c);
                super::emit(&format!("{summary}{note}\n"))?
            }
            Err(e) => {
                eprintln!("error: {e}");
                failed += 1;
            }
        }
    }
    if failed > 0 {
        return Err(format!("{failed} of {} scenes are invalid", scenes.len()));
    }
    Ok(())
}

pub fn expand(args: ExpandArgs) -> Result<(), String> {
    let ExpandArgs { scene } = args;
    let file = scene.display().to_string();
    let source = std::fs::read_to_string(&scene)
        .map_err(|e| format!("{file}: cannot read the file: {e}"))?;
    let text = kinrepro::scene::Scene::expand_text(&source, &file).map_err(|e| e.to_string())?;
    // The explicit form must assemble too.
    let explicit = kinrepro::scene::Scene::parse(&text, &file).map_err(|e| e.to_string())?;
    kinrepro::assembly::Coupling::new(&explicit).map_err(|e| format!("{file}: {e}"))?;
    super::emit(&text)
}
