//! The scalar type a seating's arithmetic is written over, so that one
//! source seats one friction vector (`f64`) or several at once in SIMD
//! lanes ([`F64x4`]: four seatings, one per lane).
//!
//! A [`Lane`] is simba's `SimdRealField` of f64 lanes, the trait nalgebra's
//! vectors, matrices and quaternions are generic over, so that
//! `Vector3<T>`, `Matrix3<T>` and their operations are the same code for
//! both. Lane i of a result equals bit for bit what the same function
//! gives for f64 on lane i's inputs: the operations are the same IEEE
//! operations in the same order (Rust contracts no `a * b + c` into a
//! fused multiply-add, and square roots and divisions are correctly
//! rounded in both), and where the scalar code branches on a value, the
//! lanes take both sides where their lanes differ and keep each lane's
//! own ([`branch`]); an iteration freezes each lane where the scalar one
//! would have stopped.

use simba::simd::{SimdBool, SimdRealField, SimdValue};

/// Four f64 lanes: simba's `WideF64x4` (`wide::f64x4`: two SSE2 or one
/// AVX register). Its arithmetic, square root and division are the IEEE
/// operations f64 uses; its sine, cosine and exponential are its own
/// polynomials, so the functions written over lanes call f64's lane by
/// lane where they need one ([`each_lane`]: a quaternion's exp of a large
/// turn, a magnet's table, the decay law), and simba's cube root of it is
/// f64's lane by lane. (simba's `AutoF64x4`, four f64 in an array, gives
/// the same bits and was 1.5x slower per seating: its operations went
/// through array maps the compiler left out of line.)
pub type F64x4 = simba::simd::WideF64x4;

/// The scalar type of a seating: f64 (one lane) or f64 lanes.
pub trait Lane:
    SimdRealField<Element = f64, SimdBool: SimdValue<Element = bool> + std::fmt::Debug> + Copy
{
}

impl<T> Lane for T where
    T: SimdRealField<Element = f64, SimdBool: SimdValue<Element = bool> + std::fmt::Debug> + Copy
{
}

/// A lane mask: `bool` for f64.
pub type Mask<T> = <T as SimdValue>::SimdBool;

/// Every lane of `T` set to `x`.
#[inline(always)]
pub fn splat<T: Lane>(x: f64) -> T {
    T::splat(x)
}

/// A vector of f64 (a fixed surface's, a body point's) in every lane.
#[inline(always)]
pub fn lift<T: Lane, const R: usize, const C: usize>(
    v: &nalgebra::SMatrix<f64, R, C>,
) -> nalgebra::SMatrix<T, R, C> {
    v.map(splat)
}

/// `then()` in the lanes where `mask` holds, `otherwise()` in the others:
/// for f64 an `if`; for lanes, each side is evaluated only if some lane
/// takes it, and both where the lanes differ (each side must then give
/// finite or infinite values, never trap, in the lanes it does not serve;
/// float arithmetic does not trap).
#[inline(always)]
pub fn branch<T: Lane, R: Select<T>>(
    mask: Mask<T>,
    then: impl FnOnce(Mask<T>) -> R,
    otherwise: impl FnOnce(Mask<T>) -> R,
) -> R {
    if mask.all() {
        then(mask)
    } else if mask.none() {
        otherwise(!mask)
    } else {
        then(mask).select_where(mask, otherwise(!mask))
    }
}

/// A value made of lanes: picks each lane from `self` where `mask` holds,
/// else from `other`.
pub trait Select<T: Lane> {
    fn select_where(self, mask: Mask<T>, other: Self) -> Self;
}

impl<T: Lane, V: SimdValue<SimdBool = Mask<T>>> Select<T> for V {
    #[inline(always)]
    fn select_where(self, mask: Mask<T>, other: Self) -> Self {
        self.select(mask, other)
    }
}

/// `f` of each lane of `a`, for a value whose f64 function has no form
/// over lanes: lane i of the result is `f` of lane i of `a` (for f64, `f`).
#[inline(always)]
pub fn each_lane<A: SimdValue, R: SimdValue>(a: &A, f: impl Fn(A::Element) -> R::Element) -> R {
    let mut r = R::splat(f(a.extract(0)));
    for i in 1..A::LANES {
        r.replace(i, f(a.extract(i)));
    }
    r
}

/// The value of lanes whose lane i is the i-th of `lanes` (one f64
/// value, vector or quaternion per lane; for f64, the first). `lanes`
/// must not be empty.
#[inline]
pub fn gather<V: SimdValue>(lanes: impl IntoIterator<Item = V::Element>) -> V {
    let mut lanes = lanes.into_iter();
    let mut v = V::splat(lanes.next().expect("gather: no lanes"));
    for (i, x) in lanes.enumerate() {
        v.replace(i + 1, x);
    }
    v
}

/// A pair of values of lanes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Both<A, B>(pub A, pub B);

impl<T: Lane, A: Select<T>, B: Select<T>> Select<T> for Both<A, B> {
    #[inline(always)]
    fn select_where(self, mask: Mask<T>, other: Self) -> Self {
        Both(self.0.select_where(mask, other.0), self.1.select_where(mask, other.1))
    }
}

/// The instruction-set extensions this build was compiled to use that the
/// CPU it runs on lacks (empty where it has them all, and off x86-64).
/// kinrepro is built for the CPU it is built on (`.cargo/config.toml`:
/// `target-cpu=native`), so a binary copied to an older machine would
/// stop on an illegal instruction; a front end asks this first and says
/// why instead.
pub fn missing_cpu_features() -> Vec<&'static str> {
    #[allow(unused_mut)]
    let mut missing = Vec::new();
    #[cfg(target_arch = "x86_64")]
    {
        macro_rules! check {
            ($($f:tt),*) => {$(
                if cfg!(target_feature = $f) && !std::arch::is_x86_feature_detected!($f) {
                    missing.push($f);
                }
            )*};
        }
        check!(
            "sse3", "ssse3", "sse4.1", "sse4.2", "popcnt", "avx", "avx2", "fma", "bmi1", "bmi2",
            "lzcnt", "f16c", "avx512f", "avx512bw", "avx512dq", "avx512vl"
        );
    }
    missing
}

/// Why this build cannot run on this CPU, if it cannot
/// ([`missing_cpu_features`]); each front end adds how to build one that
/// can.
pub fn cpu_mismatch() -> Option<String> {
    let missing = missing_cpu_features();
    (!missing.is_empty()).then(|| {
        format!(
            "this kinrepro was built for a CPU with {} and this CPU lacks them",
            missing.join(", ")
        )
    })
}
