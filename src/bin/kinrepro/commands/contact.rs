//! `kinrepro contact`: one contact pair by hand.

use kinrepro::contact::ContactPair;
use kinrepro::material::Material;

use crate::args::*;

pub fn contact(args: ContactArgs) -> Result<(), String> {
    let ContactArgs {
        shape,
        radius1,
        radius2,
        material1,
        material2,
        load,
        json,
    } = args;
    let pair = ContactPair {
        shape,
        radius1,
        radius2,
        material1: Material::builtin(&material1).map_err(|e| format!("--material1: {e}"))?,
        material2: Material::builtin(&material2).map_err(|e| format!("--material2: {e}"))?,
    };
    let eval = pair.evaluate(load).map_err(|e| e.to_string())?;
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&eval).map_err(|e| e.to_string())?
        );
    } else {
        print!("{}", kinrepro::report::contact::contact_table(&eval));
    }
    Ok(())
}
