//! Issue 12, found case 8: a failure of the nominal seating (the reference
//! every sample is measured from) is named as such, not as a sample with the
//! index usize::MAX.

use crate::common;

use kinrepro::solve::dynamic::DynamicOptions;
use kinrepro::solve::{Method, Solver};
use kinrepro::study::runner::run_variant;
use kinrepro::study::{StudyError, StudyOptions};

#[test]
fn a_failed_nominal_seating_is_named_as_such() {
    let coupling = common::load("01_maxwell_vgroove_steel.toml");
    // The dynamic solver given no time to settle after the ramp cannot
    // reach rest: the first seating it is asked for, the nominal one, fails.
    let opts = StudyOptions {
        samples: Some(5),
        replicates: Some(1),
        solver: Solver::Dynamic,
        ..StudyOptions::default()
    };
    let mut plan = common::plan(vec![coupling], &opts);
    plan.settings.method = Method::Dynamic(DynamicOptions {
        ramp_periods: 0.0,
        max_settle_periods: 1e-3,
        ..DynamicOptions::default()
    });
    let err = run_variant(&plan.settings, &plan.variants[0], &|| {}).unwrap_err();
    assert!(
        matches!(&err, StudyError::In { source, .. } if matches!(**source, StudyError::Nominal { .. })),
        "{err:?}"
    );
    let text = err.to_string();
    assert!(text.contains("the nominal seating"), "{text}");
    assert!(!text.contains(&usize::MAX.to_string()), "{text}");
    assert!(!text.contains("sample "), "{text}");
}
