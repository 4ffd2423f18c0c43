//! Accuracy of the numeric functions against the host's `std`: each function over random inputs
//! (every binade, the function's own domain, near its hard spots) and edge values (±0,
//! subnormals, the overflow thresholds, ±∞, NaN, multiples of π/2 ...), with the ulp distance to
//! `std`'s result. Each test prints the worst distance and its input (`cargo test -p il-std
//! accuracy -- --nocapture`) and fails above 1 ulp.
//!
//! On Linux `std` is glibc, whose `f64` functions are within 1 ulp of the exact result (most of
//! them correctly rounded): two results that are both within 1 ulp of the exact value are at
//! most 1 ulp apart. Two exceptions, found by this test and settled with 4000-bit arithmetic
//! (mpmath): glibc's `log10` is up to 2 ulps off (its manual says so too; libm's was within 1
//! ulp on each input where they differed by 2), so `log10` is compared with a double-double
//! computation instead ([`log10_reference`]); and at one famous hard argument of `cos` and `tan`,
//! next to a multiple of π/2, glibc is 8 and 14 ulps off while libm is correctly rounded
//! ([`HARD_CASES`]). The `f32` functions are compared with `std`'s `f64` function rounded to
//! `f32`, which is the correctly rounded result but for rare double roundings: a tighter
//! reference than glibc's own `f32` functions.

use super::*;
use std::{println, vec::Vec};

/// Random inputs per function and type, besides the edge values: fewer in debug builds, where
/// libm is unoptimised (4.4 million in all, about 2 s; the counts are printed).
const N: usize = if cfg!(debug_assertions) {
    200_000
} else {
    1_000_000
};

/// splitmix64: a small deterministic generator, so that every run checks the same inputs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + self.unit() * (hi - lo)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// An `f64` with a uniformly chosen biased exponent in `[lo, hi]` (0: subnormal), random
    /// mantissa and, if `signed`, random sign: log-uniform over those binades.
    fn binades(&mut self, lo: u64, hi: u64, signed: bool) -> f64 {
        let r = self.next();
        let e = lo + self.below(hi - lo + 1);
        let sign = if signed { r & (1 << 63) } else { 0 };
        f64::from_bits(sign | (e << 52) | (r & 0x000f_ffff_ffff_ffff))
    }

    /// The `f32` analogue of [`Rng::binades`].
    fn binadesf(&mut self, lo: u32, hi: u32, signed: bool) -> f32 {
        let r = self.next() as u32;
        let e = lo + self.below(u64::from(hi - lo + 1)) as u32;
        let sign = if signed { r & (1 << 31) } else { 0 };
        f32::from_bits(sign | (e << 23) | (r & 0x007f_ffff))
    }
}

/// Position of `x` among the `f64` values in order, `±0` both at 0.
fn ord(x: f64) -> i128 {
    let b = x.to_bits() as i64;
    i128::from(if b < 0 { i64::MIN.wrapping_sub(b) } else { b })
}

fn ordf(x: f32) -> i128 {
    let b = x.to_bits() as i32;
    i128::from(if b < 0 { i32::MIN.wrapping_sub(b) } else { b })
}

/// Ulps between two results; NaN against NaN is 0, NaN against a number and zeros of opposite
/// signs fail outright.
fn ulps(a: f64, b: f64) -> u64 {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => 0,
        (false, false) if a == 0.0 && b == 0.0 && a.is_sign_negative() != b.is_sign_negative() => {
            u64::MAX
        }
        (false, false) => (ord(a) - ord(b)).unsigned_abs() as u64,
        _ => u64::MAX,
    }
}

fn ulpsf(a: f32, b: f32) -> u64 {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => 0,
        (false, false) if a == 0.0 && b == 0.0 && a.is_sign_negative() != b.is_sign_negative() => {
            u64::MAX
        }
        (false, false) => (ordf(a) - ordf(b)).unsigned_abs() as u64,
        _ => u64::MAX,
    }
}

/// The worst case seen for one function, `(ulps, x, y, ours, std)`, and how many differed.
struct Worst {
    name: &'static str,
    count: usize,
    differ: usize,
    worst: Option<(u64, f64, f64, f64, f64)>,
}

impl Worst {
    fn new(name: &'static str) -> Self {
        Self {
            name,
            count: 0,
            differ: 0,
            worst: None,
        }
    }

    fn add(&mut self, d: u64, x: f64, y: f64, ours: f64, std: f64) {
        self.count += 1;
        self.differ += usize::from(d > 0);
        if self.worst.is_none_or(|w| d > w.0) {
            self.worst = Some((d, x, y, ours, std));
        }
    }

    /// Prints the worst case and fails if it is over 1 ulp.
    fn report(&self, binary: bool) {
        let (d, x, y, ours, std) = self.worst.unwrap_or_default();
        let arg = if binary {
            std::format!("({x:e}, {y:e})")
        } else {
            std::format!("({x:e})")
        };
        println!(
            "{:<7} {:>8} inputs, {:>6} not equal, worst {d} ulp: {}{arg} = {ours:e}, std {std:e}",
            self.name, self.count, self.differ, self.name
        );
        assert!(d <= 1, "{} over 1 ulp", self.name);
    }
}

/// Each edge value and its four neighbours on either side, as `f64` and as `f32`.
fn around(edges: &[f64]) -> (Vec<f64>, Vec<f32>) {
    let (mut v, mut vf) = (Vec::new(), Vec::new());
    for &e in edges {
        let (mut up, mut down) = (e, e);
        let (mut upf, mut downf) = (e as f32, e as f32);
        v.push(e);
        vf.push(e as f32);
        for _ in 0..4 {
            (up, down) = (up.next_up(), down.next_down());
            (upf, downf) = (upf.next_up(), downf.next_down());
            v.extend([up, down]);
            vf.extend([upf, downf]);
        }
    }
    (v, vf)
}

/// Values every function sees: zeros, subnormals, the extremes, ±∞, NaN, small integers.
const COMMON: [f64; 12] = [
    0.0,
    5e-324,
    2.225_073_858_507_201e-308,
    f64::MIN_POSITIVE,
    1.175_494_350_822_287_5e-38, // f32::MIN_POSITIVE
    1.401_298_464_324_817e-45,   // the least f32 subnormal
    f64::MAX,
    3.402_823_466_385_288_6e38, // f32::MAX
    f64::INFINITY,
    0.5,
    1.0,
    2.0,
];

/// A function's `f64` and `f32` versions and the `f64` reference.
type Versions = (fn(f64) -> f64, fn(f32) -> f32, fn(f64) -> f64);

/// A unary `f64` and `f32` pair against `std`: `domain` draws the inputs of both types (as
/// `f64`; the `f32` run rounds them), `edges` adds function-specific edge values to [`COMMON`].
fn unary(
    name: &'static str,
    namef: &'static str,
    (ours, oursf, std): Versions,
    domain: fn(&mut Rng, bool) -> f64,
    edges: &[f64],
) {
    let mut all = Vec::from(COMMON);
    all.extend_from_slice(edges);
    all.extend(all.clone().iter().map(|x| -x));
    all.push(f64::NAN);
    let (edges, edgesf) = around(&all);
    let mut w = Worst::new(name);
    let mut wf = Worst::new(namef);
    let mut rng = Rng(name.len() as u64 * 0x1234_5678 + u64::from(name.as_bytes()[0]));
    for i in 0..N + edges.len() {
        let (x, xf) = match edges.get(i).zip(edgesf.get(i)) {
            Some((&e, &ef)) => (e, ef),
            None => match rng.below(8) {
                // Any bits: every binade, both signs, now and then ∞ or NaN.
                0 => (
                    f64::from_bits(rng.next()),
                    f32::from_bits(rng.next() as u32),
                ),
                _ => (domain(&mut rng, false), domain(&mut rng, true) as f32),
            },
        };
        let s = HARD_CASES
            .iter()
            .find(|h| h.0 == name && h.1 == x.to_bits())
            .map_or_else(|| std(x), |h| f64::from_bits(h.2));
        let o = ours(x);
        w.add(ulps(o, s), x, 0.0, o, s);
        let (o, s) = (oursf(xf), std(f64::from(xf)) as f32);
        wf.add(ulpsf(o, s), f64::from(xf), 0.0, f64::from(o), f64::from(s));
    }
    w.report(false);
    wf.report(false);
}

/// Log-uniform over every positive binade of the type (`f32` when `single`).
fn positive(rng: &mut Rng, single: bool) -> f64 {
    if single {
        f64::from(rng.binadesf(0, 254, false))
    } else {
        rng.binades(0, 2046, false)
    }
}

/// Log-uniform in `±[ε/2, 1/2)` of the type: what, added to 1, is not lost.
fn small(rng: &mut Rng, single: bool) -> f64 {
    if single {
        f64::from(rng.binadesf(103, 125, true))
    } else {
        rng.binades(970, 1021, true)
    }
}

/// Log-uniform over every binade of the type, either sign.
fn any_finite(rng: &mut Rng, single: bool) -> f64 {
    if single {
        f64::from(rng.binadesf(0, 254, true))
    } else {
        rng.binades(0, 2046, true)
    }
}

#[test]
fn accuracy_sqrt() {
    unary(
        "sqrt",
        "sqrtf",
        (sqrt, sqrtf, f64::sqrt),
        positive,
        &[4.0, 0.25, 1e300],
    );
}

/// Logarithms: every binade, near 1 (where `ln` is smallest relative to `x`) and around it.
fn log_domain(rng: &mut Rng, single: bool) -> f64 {
    match rng.below(3) {
        0 => positive(rng, single),
        1 => 1.0 + small(rng, single),
        _ => rng.uniform(0.25, 4.0),
    }
}

#[test]
fn accuracy_ln() {
    unary(
        "ln",
        "lnf",
        (ln, lnf, f64::ln),
        log_domain,
        &[core::f64::consts::E, 10.0],
    );
}

#[test]
fn accuracy_log10() {
    let tens = [10.0, 100.0, 1e3, 1e5, 1e10, 1e22, 1e-1, 1e-5, 1e300, 1e-300];
    unary(
        "log10",
        "log10f",
        (log10, log10f, log10_reference),
        log_domain,
        &tens,
    );
}

/// A double-double `hi + lo`, for the `log10` reference: about 104 bits.
#[derive(Clone, Copy)]
struct Dd(f64, f64);

impl Dd {
    /// `a + b` exactly (Knuth's two-sum).
    fn sum(a: f64, b: f64) -> Self {
        let s = a + b;
        let bb = s - a;
        Self(s, (a - (s - bb)) + (b - bb))
    }

    /// `a + b` exactly when `|a| ≥ |b|`.
    fn quick(a: f64, b: f64) -> Self {
        let s = a + b;
        Self(s, b - (s - a))
    }

    fn add(self, o: Self) -> Self {
        let s = Self::sum(self.0, o.0);
        let t = Self::sum(self.1, o.1);
        let s = Self::quick(s.0, s.1 + t.0);
        Self::quick(s.0, s.1 + t.1)
    }

    fn mul(self, o: Self) -> Self {
        let p = self.0 * o.0;
        let e = self.0.mul_add(o.0, -p); // the product's rounding error, exactly
        Self::quick(p, e + (self.0 * o.1 + self.1 * o.0))
    }

    fn div(self, o: Self) -> Self {
        let q1 = self.0 / o.0;
        let r = self.add(o.mul(Self(-q1, 0.0)));
        let q2 = r.0 / o.0;
        let r = r.add(o.mul(Self(-q2, 0.0)));
        Self::quick(q1, q2).add(Self(r.0 / o.0, 0.0))
    }
}

/// `log10(x)` correctly rounded (but within 2⁻¹⁰⁰ of a tie) for positive finite `x`, `std`'s
/// elsewhere (the special values, which glibc gets right): `x = m·2ᵏ` with `m` in `[√½, √2)`,
/// `ln m = 2 atanh((m-1)/(m+1))` by its series, all in double-double.
fn log10_reference(x: f64) -> f64 {
    if !(x > 0.0 && x.is_finite()) {
        return x.log10();
    }
    const LN2: Dd = Dd(
        f64::from_bits(0x3fe6_2e42_fefa_39ef),
        f64::from_bits(0x3c7a_bc9e_3b39_803f),
    );
    const INV_LN10: Dd = Dd(
        f64::from_bits(0x3fdb_cb7b_1526_e50e),
        f64::from_bits(0x3c69_5355_baaa_fad3),
    );
    let (x, mut k) = if x < f64::MIN_POSITIVE {
        (x * 2f64.powi(54), -54)
    } else {
        (x, 0)
    };
    let bits = x.to_bits();
    k += ((bits >> 52) as i32) - 1023;
    let mut m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    if m > core::f64::consts::SQRT_2 {
        m /= 2.0;
        k += 1;
    }
    // m - 1 is exact here (Sterbenz); m + 1 is kept exactly as a double-double.
    let s = Dd(m - 1.0, 0.0).div(Dd::sum(m, 1.0));
    let s2 = s.mul(s);
    // s² ≤ 0.03, so 26 terms reach far below 2⁻¹⁰⁶.
    let mut series = Dd(0.0, 0.0);
    for i in (0..26).rev() {
        series = series
            .mul(s2)
            .add(Dd(1.0, 0.0).div(Dd(f64::from(2 * i + 1), 0.0)));
    }
    let ln = Dd(f64::from(k), 0.0)
        .mul(LN2)
        .add(s.mul(series).mul(Dd(2.0, 0.0)));
    let r = ln.mul(INV_LN10);
    r.0 + r.1
}

#[test]
fn log10_reference_is_exact_where_glibc_is_not() {
    // 4000-bit mpmath: 0.24243034230914396836…; glibc gives 0.24243034230914393, 2 ulps off.
    assert_eq!(
        log10_reference(1.747_552_945_097_265_6),
        0.242_430_342_309_143_98
    );
    assert_eq!(log10_reference(1000.0), 3.0);
    assert_eq!(log10_reference(5e-324), -323.306_215_343_115_8);
}

/// `(function, x, result)` as bits: correctly rounded results (4000-bit mpmath) where glibc is
/// off. 6381956970095103·2⁷⁹⁷ is a classic hard case of the reduction by π/2.
const HARD_CASES: [(&str, u64, u64); 4] = [
    ("cos", 0x7506_ac5b_262c_a1ff, 0xbc21_4ae7_2e6b_a22f),
    ("cos", 0xf506_ac5b_262c_a1ff, 0xbc21_4ae7_2e6b_a22f),
    ("tan", 0x7506_ac5b_262c_a1ff, 0xc3bd_9ba9_a797_5636),
    ("tan", 0xf506_ac5b_262c_a1ff, 0x43bd_9ba9_a797_5636),
];

#[test]
fn accuracy_exp() {
    fn domain(rng: &mut Rng, single: bool) -> f64 {
        let (lo, hi) = if single {
            (-104.0, 89.0)
        } else {
            (-746.0, 710.0)
        };
        match rng.below(3) {
            0 => rng.uniform(lo, hi),
            1 => rng.uniform(-2.0, 2.0),
            _ => rng.binades(900, 1022, true),
        }
    }
    let thresholds = [
        709.782_712_893_384,    // the last finite f64 result
        -708.396_418_532_264_1, // subnormal f64 results below
        -745.133_219_101_941_1, // 0 below
        88.722_84_f32 as f64,   // the last finite f32 result
        -87.336_55_f32 as f64,  // subnormal f32 results below
        -103.972_08_f32 as f64, // 0 below
        core::f64::consts::LN_2,
    ];
    unary("exp", "expf", (exp, expf, f64::exp), domain, &thresholds);
}

/// Trigonometric arguments: small, moderate, huge (where the reduction by π/2 needs many bits of
/// π), and next to multiples of π/2, where the reduced argument cancels.
fn trig_domain(rng: &mut Rng, single: bool) -> f64 {
    match rng.below(4) {
        0 => rng.uniform(-10.0, 10.0),
        1 => rng.uniform(-1e6, 1e6),
        2 => any_finite(rng, single),
        _ => {
            let k = rng.below(1 << 20) as f64 - (1 << 19) as f64;
            let x = k * core::f64::consts::FRAC_PI_2;
            if single {
                f64::from((x as f32).next_up())
            } else {
                x.next_down()
            }
        }
    }
}

/// Multiples of π/2 (as rounded to `f64`), and large ones known to be close to one.
const TRIG_EDGES: [f64; 10] = [
    core::f64::consts::FRAC_PI_2,
    core::f64::consts::PI,
    4.712_388_980_384_69,
    core::f64::consts::TAU,
    1e22,
    f64::from_bits(0x7506_ac5b_262c_a1ff), // 6381956970095103·2^797, very near one
    1.570_796_326_794_896_6e6,
    3.141_592_653_589_793e10,
    1e300,
    core::f64::consts::FRAC_PI_4,
];

#[test]
fn accuracy_sin() {
    unary(
        "sin",
        "sinf",
        (sin, sinf, f64::sin),
        trig_domain,
        &TRIG_EDGES,
    );
}

#[test]
fn accuracy_cos() {
    unary(
        "cos",
        "cosf",
        (cos, cosf, f64::cos),
        trig_domain,
        &TRIG_EDGES,
    );
}

#[test]
fn accuracy_tan() {
    unary(
        "tan",
        "tanf",
        (tan, tanf, f64::tan),
        trig_domain,
        &TRIG_EDGES,
    );
}

/// Arc sine and cosine: the whole of `[-1, 1]`, tiny values, and next to ±1 and ±0.5.
fn arc_domain(rng: &mut Rng, single: bool) -> f64 {
    match rng.below(3) {
        0 => rng.uniform(-1.0, 1.0),
        1 => rng.binades(0, 1022, true),
        _ => {
            let s = if rng.below(2) == 0 { 1.0 } else { -1.0 };
            s * (1.0 - small(rng, single).abs())
        }
    }
}

#[test]
fn accuracy_asin() {
    unary(
        "asin",
        "asinf",
        (asin, asinf, f64::asin),
        arc_domain,
        &[0.975],
    );
}

#[test]
fn accuracy_acos() {
    unary(
        "acos",
        "acosf",
        (acos, acosf, f64::acos),
        arc_domain,
        &[0.975],
    );
}

#[test]
fn accuracy_atan() {
    fn domain(rng: &mut Rng, single: bool) -> f64 {
        if rng.below(2) == 0 {
            rng.uniform(-4.0, 4.0)
        } else {
            any_finite(rng, single)
        }
    }
    // The bounds of fdlibm's argument ranges, and where atan(x) rounds to ±π/2.
    let edges = [
        0.4375,
        0.6875,
        1.1875,
        2.4375,
        1e16,
        7.378_697_629_483_821e19,
    ];
    unary("atan", "atanf", (atan, atanf, f64::atan), domain, &edges);
}

/// Exponents for `pow`: zeros, ±1, small and large integers (odd and even), halves, ±∞, NaN.
const EXPONENTS: [f64; 22] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    2.0,
    -2.0,
    3.0,
    -3.0,
    0.5,
    -0.5,
    1.5,
    64.0,
    65.0,
    -1075.0,
    1e20,
    9_007_199_254_740_991.0, // 2^53 - 1, odd
    16_777_217.0,            // 2^24 + 1, odd: not an f32
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    0.1, // not an f32
    f64::MIN_POSITIVE,
];

/// Bases for `pow` (and their negatives).
const BASES: [f64; 14] = [
    0.0,
    1.0,
    0.5,
    2.0,
    8.0,
    10.0,
    1.000_000_000_000_000_2,
    0.999_999_999_999_999_9,
    1.000_000_119_209_289_6, // the f32 after 1
    5e-324,
    f64::MIN_POSITIVE,
    f64::MAX,
    f64::INFINITY,
    f64::NAN,
];

/// A `pow` input pair of the type (`f32` base when `single`): bases over every binade with
/// exponents that keep the result about in range, negative bases with integer exponents, bases
/// next to 1 with huge exponents, small integers (exact results), and any bits.
fn pow_pair(rng: &mut Rng, single: bool) -> (f64, f64) {
    let span = if single { 160.0 } else { 1100.0 };
    let base = |rng: &mut Rng| {
        if single {
            f64::from(rng.binadesf(1, 254, false))
        } else {
            rng.binades(1, 2046, false)
        }
    };
    match rng.below(6) {
        0 => {
            let x = base(rng);
            (x, rng.uniform(-span, span) / x.log2())
        }
        1 => {
            let x = base(rng);
            (-x, (rng.uniform(-span, span) / x.log2()).round())
        }
        2 => {
            // 1 ± a few ulps, to odd integer or real exponents around 1/ulp.
            let ulp = if single {
                f64::from(f32::EPSILON)
            } else {
                f64::EPSILON
            };
            let x = 1.0 + ulp * (rng.below(16) as f64 - 8.0);
            let y = (rng.uniform(-8.0, 8.0) / ulp).round();
            let y = match rng.below(3) {
                0 => y + 1.0 - y % 2.0,
                1 => y + rng.unit(),
                // An f32 exponent, which takes powf's own path for a REAL base.
                _ => f64::from(y as f32),
            };
            (if rng.below(2) == 0 { x } else { -x }, y)
        }
        3 => (rng.below(21) as f64 - 10.0, rng.below(41) as f64 - 20.0),
        4 => (rng.uniform(0.0, 10.0), rng.uniform(-30.0, 30.0)),
        _ => (f64::from_bits(rng.next()), f64::from_bits(rng.next())),
    }
}

#[test]
fn accuracy_pow() {
    let mut pairs = Vec::new();
    for &x in &BASES {
        for &y in &EXPONENTS {
            pairs.extend([(x, y), (-x, y), (x, -y), (-x, -y)]);
        }
    }
    let mut w = Worst::new("pow");
    let mut wf = Worst::new("powf");
    let mut rng = Rng(0x0070_6f77);
    for i in 0..N + pairs.len() {
        let ((x, y), (xf, yf)) = match pairs.get(i) {
            Some(&p) => (p, p),
            None => (pow_pair(&mut rng, false), pow_pair(&mut rng, true)),
        };
        let (o, s) = (pow(x, y), x.powf(y));
        w.add(ulps(o, s), x, y, o, s);
        // The REAL base is an f32; the exponent stays f64 (an integer of any IEC type).
        let xf = xf as f32;
        let (o, s) = (powf(xf, yf), f64::from(xf).powf(yf) as f32);
        wf.add(ulpsf(o, s), f64::from(xf), yf, f64::from(o), f64::from(s));
    }
    w.report(true);
    wf.report(true);
}
