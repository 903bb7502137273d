//! Checks of a study's results before they are reported: non-finite or
//! overflowing outputs (an error naming the sample, never sigma = 0) and a
//! coupling that did not seat (zero scatter).

use crate::report::study_record::{PointStats, StudyRecord};
use crate::report::study_stream::check_record;
use crate::study::StudyError;

/// Every output finite, and no column so large that its sum of squares
/// overflows (that would make sigma NaN): otherwise an error naming the
/// sample.
pub(crate) fn check_finite_records(
    records: &[StudyRecord],
    names: &[String],
) -> Result<(), StudyError> {
    for r in records {
        check_record(r.index, &r.outputs, names)?;
    }
    let n = records.len() as f64;
    for (k, name) in names.iter().enumerate() {
        let worst = records
            .iter()
            .max_by(|a, b| a.outputs[k].abs().total_cmp(&b.outputs[k].abs()));
        if let Some(r) = worst
            && !(r.outputs[k] * r.outputs[k] * n).is_finite()
        {
            return Err(StudyError::NonFinite {
                what: format!(
                    "sample {}: output {} = {:e} overflows the variance",
                    r.index, name, r.outputs[k]
                ),
            });
        }
    }
    Ok(())
}

/// The reason a study's coupling did not seat: every re-seating sigma is
/// exactly zero, i.e. every sample stopped at the nominal pose and nothing
/// slid (above the friction limit every contact sticks from the first
/// load increment).
pub(crate) fn zero_scatter(points: &[PointStats]) -> Option<String> {
    let zero = !points.is_empty()
        && points
            .iter()
            .all(|p| p.sigma.values().iter().all(|s| *s == 0.0));
    zero.then(|| {
        "zero scatter: every sample seated at exactly the nominal pose, nothing slid; the coupling cannot seat (friction at or above its seating limit, see `kinrepro check`)".to_string()
    })
}
