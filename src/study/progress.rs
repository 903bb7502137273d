//! What a study run reports as it goes ([`Progress`]): a tick per
//! finished sample and, where asked, the path of every seating.

use super::paths::PathTally;
use crate::solve::SeatedPose;

/// What a run reports as it goes: `tick` once per finished sample, and
/// the path of every sample seating counted into `tally` where one is
/// given. A closure alone is a `Progress` without a tally.
#[derive(Clone, Copy)]
pub struct Progress<'a> {
    pub tick: &'a (dyn Fn() + Sync),
    pub tally: Option<&'a PathTally>,
}

impl<'a> Progress<'a> {
    /// `tick` per sample, the seating paths counted into `tally`.
    pub fn with_tally(tick: &'a (dyn Fn() + Sync), tally: &'a PathTally) -> Self {
        Progress { tick, tally: Some(tally) }
    }

    pub(super) fn record(&self, seated: &SeatedPose) {
        if let Some(t) = self.tally {
            t.record(seated);
        }
    }
}

impl<'a, F: Fn() + Sync> From<&'a F> for Progress<'a> {
    fn from(tick: &'a F) -> Self {
        Progress { tick, tally: None }
    }
}

impl<'a> From<&'a (dyn Fn() + Sync + 'a)> for Progress<'a> {
    fn from(tick: &'a (dyn Fn() + Sync + 'a)) -> Self {
        Progress { tick, tally: None }
    }
}
