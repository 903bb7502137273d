//! The bundled paper scenes, compiled in.

/// The seven paper variants (Table 1), built into the program so that
/// `validate-hertz` works wherever it runs: (file name, TOML text).
pub const PAPER_SCENES: [(&str, &str); 7] = [
    (
        "scenes/01_maxwell_vgroove_steel.toml",
        include_str!("../../scenes/01_maxwell_vgroove_steel.toml"),
    ),
    ("scenes/02_maxwell_pins_steel.toml", include_str!("../../scenes/02_maxwell_pins_steel.toml")),
    ("scenes/03_maxwell_pins_sic.toml", include_str!("../../scenes/03_maxwell_pins_sic.toml")),
    (
        "scenes/04_maxwell_balls_steel.toml",
        include_str!("../../scenes/04_maxwell_balls_steel.toml"),
    ),
    ("scenes/05_maxwell_balls_sic.toml", include_str!("../../scenes/05_maxwell_balls_sic.toml")),
    ("scenes/06_kelvin_steel.toml", include_str!("../../scenes/06_kelvin_steel.toml")),
    ("scenes/07_kelvin_sic.toml", include_str!("../../scenes/07_kelvin_sic.toml")),
];
