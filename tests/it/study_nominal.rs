//! Issue 12, found case 8: a failure of the nominal seating (the reference
//! every sample is measured from) is named as such, not as a sample with the
//! index usize::MAX.

use crate::common;

use kinrepro::solve::Method;
use kinrepro::solve::dynamic::DynamicOptions;
use kinrepro::study::runner::{RunError, StudyOptions, run_variant};

#[test]
fn a_failed_nominal_seating_is_named_as_such() {
    let coupling = common::load("01_maxwell_vgroove_steel.toml");
    // The dynamic solver given no time to settle after the ramp cannot
    // reach rest: the first seating it is asked for, the nominal one, fails.
    let opts = StudyOptions {
        samples: Some(5),
        replicates: Some(1),
        method: Method::Dynamic(DynamicOptions {
            ramp_periods: 0.0,
            max_settle_periods: 1e-3,
            ..DynamicOptions::default()
        }),
        ..StudyOptions::default()
    };
    let err = run_variant(&coupling, &opts, &|| {}).unwrap_err();
    assert!(matches!(err, RunError::Nominal { .. }), "{err:?}");
    let text = err.to_string();
    assert!(text.contains("the nominal seating"), "{text}");
    assert!(!text.contains(&usize::MAX.to_string()), "{text}");
    assert!(!text.contains("sample "), "{text}");
}
