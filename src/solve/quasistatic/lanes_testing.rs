//! What the lane tests of the seating share (`newton_lanes`, `path_lanes`):
//! four seatings' frictions and poses, and their forms over lanes.

use rand::Rng;

use crate::assembly::{BodyPose, Coupling};
use crate::contact::Friction;
use crate::lane::F64x4;
use crate::solve::contact_lanes::LaneFriction;
use crate::solve::frictions_into;

/// Four seatings' frictions of `c`'s contacts (`[lane][contact]`), mu
/// drawn from `range`.
pub fn draw_frictions(
    rng: &mut impl Rng,
    c: &Coupling,
    range: std::ops::Range<f64>,
) -> Vec<Vec<Friction>> {
    (0..4)
        .map(|_| {
            let mu: Vec<f64> =
                (0..c.contacts.len()).map(|_| rng.random_range(range.clone())).collect();
            let mut f = Vec::new();
            frictions_into(c, &mu, &mut f).unwrap();
            f
        })
        .collect()
}

/// The four seatings' frictions as one per contact over lanes.
pub fn lane_frictions(frictions: &[Vec<Friction>]) -> Vec<LaneFriction<F64x4>> {
    (0..frictions[0].len())
        .map(|i| LaneFriction::from_frictions(&[0, 1, 2, 3].map(|l| &frictions[l][i])))
        .collect()
}

/// Four poses as one pose of lanes.
pub fn pose_lanes(p: &[BodyPose; 4]) -> BodyPose<F64x4> {
    BodyPose::from_lanes(p)
}
