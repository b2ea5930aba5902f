//! Vectors of `f64` for the integration kernels, so each formula is written once (generic over
//! [`Real`]) and runs on one face or triangle per lane:
//! - `f64`: one lane, any CPU;
//! - `F64x4`: four lanes, x86-64 with AVX2 and FMA;
//! - `F64x8`: eight lanes, x86-64 with AVX-512 (F, VL, DQ).
//!
//! Corners are loaded by [`Real::gather`], one vertex per lane, and transposed into x, y, z
//! vectors in registers. Per-lane choices (Mirtich's projection plane) are masks and selects, so
//! every lane runs the same instructions.
//!
//! Soundness: the x86 types wrap the intrinsics of their instruction set, which must not run on
//! a CPU without it. The types are private to this module, so the only code that ever handles
//! them is a [`Kernel`] instantiated here, inside a function compiled for that instruction set
//! (`#[target_feature]`), which [`Level::run`] enters only after detecting the features at run
//! time.
#![allow(unsafe_code)]

use std::ops::{Add, AddAssign, BitAnd, Div, Mul, Neg, Sub};

use nalgebra::Point3;

/// The instruction sets the kernels are compiled for, best last.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Level {
    /// One lane of plain `f64` arithmetic.
    Portable,
    /// `F64x4`.
    Avx2,
    /// `F64x8`.
    Avx512,
}

impl Level {
    /// The best level this CPU supports.
    pub(crate) fn detect() -> Level {
        Self::ALL
            .into_iter()
            .rev()
            .find(|l| l.is_supported())
            .unwrap_or(Level::Portable)
    }

    /// Every level this CPU supports, `Portable` first; prints the others to stderr, so a test
    /// run says which kernels it did not check. Written to the stream itself: `eprintln!` is
    /// captured by the test harness and shown only when a test fails.
    #[cfg(test)]
    pub(crate) fn available() -> Vec<Level> {
        use std::io::Write as _;
        for (level, why) in Self::unavailable() {
            let _ = writeln!(std::io::stderr(), "not tested here: {level:?} ({why})");
        }
        Self::ALL.into_iter().filter(|l| l.is_supported()).collect()
    }

    /// Every level this CPU lacks, each with the reason, for tests to say what they did not
    /// cover (a test that only loops over [`Level::available`] passes silently without them).
    #[cfg(test)]
    pub(crate) fn unavailable() -> Vec<(Level, String)> {
        Self::ALL
            .into_iter()
            .filter(|l| !l.is_supported())
            .map(|l| (l, l.missing_features()))
            .collect()
    }

    /// Why this CPU cannot run `self`: the features it lacks.
    #[cfg(test)]
    fn missing_features(self) -> String {
        #[cfg(target_arch = "x86_64")]
        {
            let needed: &[&str] = match self {
                Level::Portable => &[],
                Level::Avx2 => &["avx2", "fma"],
                Level::Avx512 => &["avx2", "fma", "avx512f", "avx512vl", "avx512dq"],
            };
            // `is_x86_feature_detected!` takes literals only, hence the match.
            let has = |f: &str| match f {
                "avx2" => std::arch::is_x86_feature_detected!("avx2"),
                "fma" => std::arch::is_x86_feature_detected!("fma"),
                "avx512f" => std::arch::is_x86_feature_detected!("avx512f"),
                "avx512vl" => std::arch::is_x86_feature_detected!("avx512vl"),
                "avx512dq" => std::arch::is_x86_feature_detected!("avx512dq"),
                _ => false,
            };
            let lacking: Vec<&str> = needed.iter().copied().filter(|f| !has(f)).collect();
            format!("CPU lacks {}", lacking.join(", "))
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = self;
            "not an x86-64 CPU".to_owned()
        }
    }

    const ALL: [Level; 3] = [Level::Portable, Level::Avx2, Level::Avx512];

    fn is_supported(self) -> bool {
        match self {
            Level::Portable => true,
            #[cfg(target_arch = "x86_64")]
            Level::Avx2 => {
                std::arch::is_x86_feature_detected!("avx2")
                    && std::arch::is_x86_feature_detected!("fma")
            }
            #[cfg(target_arch = "x86_64")]
            Level::Avx512 => {
                Level::Avx2.is_supported()
                    && std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("avx512dq")
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// Runs `kernel` with the vector type of this level, inside a function compiled for its
    /// instruction set; a level the CPU lacks runs the portable kernel.
    #[inline(always)]
    pub(crate) fn run<K: Kernel>(self, kernel: K) -> K::Output {
        #[cfg(target_arch = "x86_64")]
        match self {
            Level::Avx512 if self.is_supported() => {
                // SAFETY: the CPU has every feature `run_avx512` is compiled with (checked just
                // above).
                return unsafe { run_avx512(kernel) };
            }
            Level::Avx2 if self.is_supported() => {
                // SAFETY: as above, for AVX2 and FMA.
                return unsafe { run_avx2(kernel) };
            }
            _ => {}
        }
        kernel.run::<f64>()
    }
}

/// A computation generic over the vector type, for [`Level::run`].
pub(crate) trait Kernel {
    type Output;
    fn run<T: Real>(self) -> Self::Output;
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512dq,avx2,fma")]
fn run_avx512<K: Kernel>(kernel: K) -> K::Output {
    kernel.run::<F64x8>()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn run_avx2<K: Kernel>(kernel: K) -> K::Output {
    kernel.run::<F64x4>()
}

/// Asks the CPU to start loading `value`'s cache line (a hint: no effect on results).
#[inline(always)]
pub(crate) fn prefetch<T>(value: &T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch never faults, and SSE is part of the x86-64 baseline.
    unsafe {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        _mm_prefetch::<_MM_HINT_T0>((value as *const T).cast());
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = value;
}

/// The arithmetic of the kernels, lane by lane.
pub(crate) trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
{
    /// One boolean per lane.
    type Mask: Copy + BitAnd<Output = Self::Mask>;
    /// Number of lanes.
    const LANES: usize;

    /// `v` in every lane.
    fn splat(v: f64) -> Self;
    /// `self·b + c`, fused (one rounding) in the vector types, plain in `f64`, whose portable
    /// `mul_add` is a slow library call on CPUs without FMA.
    fn mul_add(self, b: Self, c: Self) -> Self;
    fn abs(self) -> Self;
    /// `self ≥ other` (false where either is NaN).
    fn ge(self, other: Self) -> Self::Mask;
    /// Lanes that are finite and non-zero.
    fn is_finite_nonzero(self) -> Self::Mask;
    /// `yes` where the mask is set, else `no`.
    fn select(mask: Self::Mask, yes: Self, no: Self) -> Self;
    /// The power of two s that brings |self| into [1, 2), for finite non-zero |self| < 2¹⁰²³
    /// (subnormals get 2¹⁰²³; |self| ≥ 2¹⁰²³ gets 0, and infinities and NaN get −∞: callers mask
    /// those lanes, or would overflow anyway at such sizes).
    fn scale_to_unit_exponent(self) -> Self;
    /// Sum of the lanes, in a fixed order (so results are reproducible).
    fn sum_lanes(self) -> f64;
    /// The x, y and z coordinates, relative to `reference`, of corner `corner` of faces
    /// `faces[0..LANES]` (one face per lane).
    fn gather<const N: usize>(
        positions: &[Point3<f64>],
        reference: Point3<f64>,
        faces: &[[u32; N]],
        corner: usize,
    ) -> [Self; 3];
}

/// Bits of the exponent field of an `f64`.
const EXPONENT_BITS: u64 = 0x7FF0_0000_0000_0000;
/// 2046 in the exponent field: s = 2^(1023 − e) has field 2046 − field(e).
const TWICE_BIAS: u64 = 0x7FE0_0000_0000_0000;

impl Real for f64 {
    type Mask = bool;
    const LANES: usize = 1;

    #[inline(always)]
    fn splat(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        self * b + c
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64::abs(self)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> bool {
        self >= other
    }
    #[inline(always)]
    fn is_finite_nonzero(self) -> bool {
        self != 0.0 && self.is_finite()
    }
    #[inline(always)]
    fn select(mask: bool, yes: Self, no: Self) -> Self {
        if mask { yes } else { no }
    }
    #[inline(always)]
    fn scale_to_unit_exponent(self) -> Self {
        f64::from_bits(TWICE_BIAS.wrapping_sub(self.to_bits() & EXPONENT_BITS))
    }
    #[inline(always)]
    fn sum_lanes(self) -> f64 {
        self
    }
    #[inline(always)]
    fn gather<const N: usize>(
        positions: &[Point3<f64>],
        reference: Point3<f64>,
        faces: &[[u32; N]],
        corner: usize,
    ) -> [Self; 3] {
        let p = positions[faces[0][corner] as usize] - reference;
        [p.x, p.y, p.z]
    }
}

#[cfg(target_arch = "x86_64")]
use x86::{F64x4, F64x8};

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;
    use std::ops::{Add, AddAssign, BitAnd, Div, Mul, Neg, Sub};

    use nalgebra::Point3;

    use super::{EXPONENT_BITS, Real, TWICE_BIAS};

    /// Implements the arithmetic operators of a vector type with the given intrinsics.
    macro_rules! arithmetic {
        ($ty:ident, $add:ident, $sub:ident, $mul:ident, $div:ident, $xor:ident, $set1:ident) => {
            impl Add for $ty {
                type Output = Self;
                #[inline(always)]
                fn add(self, rhs: Self) -> Self {
                    // SAFETY: see the module doc (values exist only where the ISA is enabled).
                    Self(unsafe { $add(self.0, rhs.0) })
                }
            }
            impl AddAssign for $ty {
                #[inline(always)]
                fn add_assign(&mut self, rhs: Self) {
                    *self = *self + rhs;
                }
            }
            impl Sub for $ty {
                type Output = Self;
                #[inline(always)]
                fn sub(self, rhs: Self) -> Self {
                    // SAFETY: as for `add`.
                    Self(unsafe { $sub(self.0, rhs.0) })
                }
            }
            impl Mul for $ty {
                type Output = Self;
                #[inline(always)]
                fn mul(self, rhs: Self) -> Self {
                    // SAFETY: as for `add`.
                    Self(unsafe { $mul(self.0, rhs.0) })
                }
            }
            impl Div for $ty {
                type Output = Self;
                #[inline(always)]
                fn div(self, rhs: Self) -> Self {
                    // SAFETY: as for `add`.
                    Self(unsafe { $div(self.0, rhs.0) })
                }
            }
            impl Neg for $ty {
                type Output = Self;
                #[inline(always)]
                fn neg(self) -> Self {
                    // SAFETY: as for `add`; flips the sign bit, as scalar negation does.
                    Self(unsafe { $xor(self.0, $set1(-0.0)) })
                }
            }
        };
    }

    /// Four lanes in an AVX2 register.
    #[derive(Clone, Copy)]
    pub(super) struct F64x4(__m256d);

    /// Lane mask of [`F64x4`]: all bits set in a true lane.
    #[derive(Clone, Copy)]
    pub(super) struct Mask4(__m256d);

    impl BitAnd for Mask4 {
        type Output = Self;
        #[inline(always)]
        fn bitand(self, rhs: Self) -> Self {
            // SAFETY: as for `F64x4::add`.
            Self(unsafe { _mm256_and_pd(self.0, rhs.0) })
        }
    }

    arithmetic!(
        F64x4,
        _mm256_add_pd,
        _mm256_sub_pd,
        _mm256_mul_pd,
        _mm256_div_pd,
        _mm256_xor_pd,
        _mm256_set1_pd
    );

    impl Real for F64x4 {
        type Mask = Mask4;
        const LANES: usize = 4;

        #[inline(always)]
        fn splat(v: f64) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm256_set1_pd(v) })
        }
        #[inline(always)]
        fn mul_add(self, b: Self, c: Self) -> Self {
            // SAFETY: see the module doc (FMA is enabled with AVX2 in every kernel).
            Self(unsafe { _mm256_fmadd_pd(self.0, b.0, c.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0) })
        }
        #[inline(always)]
        fn ge(self, other: Self) -> Mask4 {
            // SAFETY: see the module doc.
            Mask4(unsafe { _mm256_cmp_pd::<_CMP_GE_OQ>(self.0, other.0) })
        }
        #[inline(always)]
        fn is_finite_nonzero(self) -> Mask4 {
            let a = self.abs();
            // SAFETY: see the module doc.
            unsafe {
                let positive = _mm256_cmp_pd::<_CMP_GT_OQ>(a.0, _mm256_setzero_pd());
                let finite = _mm256_cmp_pd::<_CMP_LT_OQ>(a.0, _mm256_set1_pd(f64::INFINITY));
                Mask4(_mm256_and_pd(positive, finite))
            }
        }
        #[inline(always)]
        fn select(mask: Mask4, yes: Self, no: Self) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm256_blendv_pd(no.0, yes.0, mask.0) })
        }
        #[inline(always)]
        fn scale_to_unit_exponent(self) -> Self {
            // SAFETY: see the module doc.
            unsafe {
                let exponent = _mm256_and_si256(
                    _mm256_castpd_si256(self.0),
                    _mm256_set1_epi64x(EXPONENT_BITS as i64),
                );
                let bits = _mm256_sub_epi64(_mm256_set1_epi64x(TWICE_BIAS as i64), exponent);
                Self(_mm256_castsi256_pd(bits))
            }
        }
        #[inline(always)]
        fn sum_lanes(self) -> f64 {
            let mut l = [0.0; 4];
            // SAFETY: see the module doc; `l` holds four f64.
            unsafe { _mm256_storeu_pd(l.as_mut_ptr(), self.0) };
            (l[0] + l[1]) + (l[2] + l[3])
        }
        #[inline(always)]
        fn gather<const N: usize>(
            positions: &[Point3<f64>],
            reference: Point3<f64>,
            faces: &[[u32; N]],
            corner: usize,
        ) -> [Self; 3] {
            // Plain calls, not closures: those are not reliably inlined into the kernels'
            // target-feature context.
            let r0 = load_point4(&positions[faces[0][corner] as usize]);
            let r1 = load_point4(&positions[faces[1][corner] as usize]);
            let r2 = load_point4(&positions[faces[2][corner] as usize]);
            let r3 = load_point4(&positions[faces[3][corner] as usize]);
            // SAFETY: see the module doc.
            let [x, y, z] = unsafe {
                // [x0 x1 z0 z1], [y0 y1 · ·], [x2 x3 z2 z3], [y2 y3 · ·]
                let (lo01, hi01) = (_mm256_unpacklo_pd(r0, r1), _mm256_unpackhi_pd(r0, r1));
                let (lo23, hi23) = (_mm256_unpacklo_pd(r2, r3), _mm256_unpackhi_pd(r2, r3));
                [
                    _mm256_permute2f128_pd::<0x20>(lo01, lo23),
                    _mm256_permute2f128_pd::<0x20>(hi01, hi23),
                    _mm256_permute2f128_pd::<0x31>(lo01, lo23),
                ]
            };
            [
                Self(x) - Self::splat(reference.x),
                Self(y) - Self::splat(reference.y),
                Self(z) - Self::splat(reference.z),
            ]
        }
    }

    /// [x, y, z, 0] of one point.
    #[inline(always)]
    fn load_point4(p: &Point3<f64>) -> __m256d {
        // SAFETY: see the module doc; `p` is three contiguous f64 (nalgebra's storage is
        // `repr(C)`) and the mask loads only those three.
        unsafe { _mm256_maskload_pd(p.coords.as_ptr(), _mm256_setr_epi64x(-1, -1, -1, 0)) }
    }

    /// Eight lanes in an AVX-512 register.
    #[derive(Clone, Copy)]
    pub(super) struct F64x8(__m512d);

    arithmetic!(
        F64x8,
        _mm512_add_pd,
        _mm512_sub_pd,
        _mm512_mul_pd,
        _mm512_div_pd,
        _mm512_xor_pd,
        _mm512_set1_pd
    );

    impl Real for F64x8 {
        type Mask = __mmask8;
        const LANES: usize = 8;

        #[inline(always)]
        fn splat(v: f64) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm512_set1_pd(v) })
        }
        #[inline(always)]
        fn mul_add(self, b: Self, c: Self) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm512_fmadd_pd(self.0, b.0, c.0) })
        }
        #[inline(always)]
        fn abs(self) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm512_abs_pd(self.0) })
        }
        #[inline(always)]
        fn ge(self, other: Self) -> __mmask8 {
            // SAFETY: see the module doc.
            unsafe { _mm512_cmp_pd_mask::<_CMP_GE_OQ>(self.0, other.0) }
        }
        #[inline(always)]
        fn is_finite_nonzero(self) -> __mmask8 {
            let a = self.abs();
            // SAFETY: see the module doc.
            unsafe {
                _mm512_cmp_pd_mask::<_CMP_GT_OQ>(a.0, _mm512_setzero_pd())
                    & _mm512_cmp_pd_mask::<_CMP_LT_OQ>(a.0, _mm512_set1_pd(f64::INFINITY))
            }
        }
        #[inline(always)]
        fn select(mask: __mmask8, yes: Self, no: Self) -> Self {
            // SAFETY: see the module doc.
            Self(unsafe { _mm512_mask_blend_pd(mask, no.0, yes.0) })
        }
        #[inline(always)]
        fn scale_to_unit_exponent(self) -> Self {
            // SAFETY: see the module doc.
            unsafe {
                let exponent = _mm512_and_si512(
                    _mm512_castpd_si512(self.0),
                    _mm512_set1_epi64(EXPONENT_BITS as i64),
                );
                let bits = _mm512_sub_epi64(_mm512_set1_epi64(TWICE_BIAS as i64), exponent);
                Self(_mm512_castsi512_pd(bits))
            }
        }
        #[inline(always)]
        fn sum_lanes(self) -> f64 {
            // SAFETY: see the module doc.
            let halves = unsafe {
                _mm256_add_pd(
                    _mm512_castpd512_pd256(self.0),
                    _mm512_extractf64x4_pd::<1>(self.0),
                )
            };
            F64x4(halves).sum_lanes()
        }
        #[inline(always)]
        fn gather<const N: usize>(
            positions: &[Point3<f64>],
            reference: Point3<f64>,
            faces: &[[u32; N]],
            corner: usize,
        ) -> [Self; 3] {
            // Plain calls, not closures: those are not reliably inlined into the kernels'
            // target-feature context.
            let p04 = load_pair(positions, faces[0][corner], faces[4][corner]);
            let p15 = load_pair(positions, faces[1][corner], faces[5][corner]);
            let p26 = load_pair(positions, faces[2][corner], faces[6][corner]);
            let p37 = load_pair(positions, faces[3][corner], faces[7][corner]);
            // SAFETY: see the module doc.
            let [x, y, z] = unsafe {
                // [x0 x1 z0 z1 x4 x5 z4 z5], [y0 y1 · · y4 y5 · ·], and the same for 2, 3, 6, 7.
                let (lo01, hi01) = (_mm512_unpacklo_pd(p04, p15), _mm512_unpackhi_pd(p04, p15));
                let (lo23, hi23) = (_mm512_unpacklo_pd(p26, p37), _mm512_unpackhi_pd(p26, p37));
                let first = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13);
                let second = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
                [
                    _mm512_permutex2var_pd(lo01, first, lo23),
                    _mm512_permutex2var_pd(hi01, first, hi23),
                    _mm512_permutex2var_pd(lo01, second, lo23),
                ]
            };
            [
                Self(x) - Self::splat(reference.x),
                Self(y) - Self::splat(reference.y),
                Self(z) - Self::splat(reference.z),
            ]
        }
    }

    /// [x, y, z, 0] of points i and j side by side.
    #[inline(always)]
    fn load_pair(positions: &[Point3<f64>], i: u32, j: u32) -> __m512d {
        let (p, q) = (&positions[i as usize], &positions[j as usize]);
        // SAFETY: see the module doc; `p` and `q` are three contiguous f64 each (nalgebra's
        // storage is `repr(C)`) and the masks load only those three.
        unsafe {
            let low = _mm256_maskz_loadu_pd(0b0111, p.coords.as_ptr());
            let high = _mm256_maskz_loadu_pd(0b0111, q.coords.as_ptr());
            _mm512_insertf64x4::<1>(_mm512_castpd256_pd512(low), high)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_level_is_either_available_or_reported_missing() {
        let available = Level::available();
        let unavailable = Level::unavailable();
        assert_eq!(available.first(), Some(&Level::Portable));
        for level in Level::ALL {
            let missing = unavailable.iter().find(|(l, _)| *l == level);
            assert_ne!(available.contains(&level), missing.is_some(), "{level:?}");
            if let Some((_, why)) = missing {
                // Names what is lacking: a bare "CPU lacks " would tell the reader nothing.
                assert!(!why.ends_with("lacks "), "{level:?}: {why}");
            }
        }
        assert_eq!(available.len() + unavailable.len(), Level::ALL.len());
    }
}
