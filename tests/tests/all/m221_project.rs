//! `m221/groups.smbp`, a Modicon M221 project written for the tests (one
//! rung per instruction group), compiled by build.rs and by `il!` and run
//! scan by scan against the trace `ilc run` is checked against
//! (il-cli/tests/all/m221.rs): the same inputs, the same values.

use il_std::{Area, Cycle, TIME};

/// Inputs %I0.0 .. %I0.7 per scan (bit j of the byte is %I0.j).
const INPUTS: [u8; 6] = [
    0b0010_0001, // I0.0, I0.5
    0b1011_0001, // + I0.4, I0.7
    0b0011_0011, // I0.1; I0.7 falls
    0b1010_1010, // I0.0 falls, I0.3, I0.7; I0.4 falls
    0b0011_1110, // I0.2, I0.4; I0.7 falls
    0b0111_1110, // + I0.6
];

/// ([Q0.0, M1, Q0.7, M0, Q0.1, Q0.2, Q0.3, Q0.4, Q0.5, Q0.6], C0.V, MW0, MW1,
/// MF10) after each scan, worked out by hand (see il-cli's test for why).
type Scan = ([bool; 10], i16, i16, i16, f32);

const F: bool = false;
const T: bool = true;

const TRACE: [Scan; 6] = [
    ([F, F, F, F, F, F, F, F, F, F], 0, 0, -1, -0.5),
    ([F, F, F, T, F, T, T, F, F, F], 1, 1, 2, 1.0),
    ([T, F, F, T, T, F, T, F, F, F], 1, 1, 2, 1.0),
    ([F, T, T, F, F, F, F, T, T, T], 2, 2, 5, 2.5),
    ([F, T, T, T, T, F, F, T, T, T], 2, 2, 5, 2.5),
    ([F, T, T, T, T, F, F, T, F, T], 0, 2, 5, 2.5),
];

macro_rules! scans {
    ($m:ident) => {{
        use il_tests::$m::M221;
        let mut ctx = Cycle::new();
        let mut p = M221::default();
        for (k, want) in TRACE.iter().enumerate() {
            ctx.set_now(TIME::from_ms(10 * k as i64));
            ctx.io.set_byte(Area::Input, 0, INPUTS[k]);
            p.run(&mut ctx);
            let q = |j: u8| ctx.io.bit(Area::Output, 0, j);
            let got = (
                [q(0), p.M1, q(7), p.M0, q(1), q(2), q(3), q(4), q(5), q(6)],
                p.C0.V,
                p.MW0,
                p.MW1,
                p.MF10,
            );
            assert_eq!(got, *want, "{} scan {}", stringify!($m), k + 1);
        }
    }};
}

#[test]
fn the_project_runs_through_build_rs() {
    scans!(m221_build);
}

#[test]
fn the_project_runs_through_il() {
    scans!(m221_macro);
}

/// `m221/ends.smbp` through build.rs: ENDC in the first POU ends the scan
/// (the second POU does not run), ENDCN in the second skips its last rung,
/// `%MW2:X1` and `%MW4:X0` are bits of words. The trace of il-cli's test.
#[test]
fn the_end_of_scan_project_runs_through_build_rs() {
    use il_tests::m221_ends::M221;
    // (I0.0, I0.1, I0.2) per scan, and (MW2, Q0.0, MW3, MW4, MW5, MW6) after.
    let inputs = [
        (F, F, T),
        (F, T, T),
        (T, T, T),
        (F, F, T),
        (F, F, F),
        (F, F, F),
    ];
    let want: [(i16, bool, i16, i16, i16, i16); 6] = [
        (1, F, 1, 0, 1, 16),
        (2, T, 2, 1, 2, 32),
        (2, T, 2, 1, 2, 32),
        (3, T, 3, 0, 3, 48),
        (4, F, 4, 0, 3, 64),
        (5, F, 5, 0, 3, 80),
    ];
    let mut ctx = Cycle::new();
    let mut p = M221::default();
    for (k, ((a, b, c), want)) in inputs.iter().zip(want).enumerate() {
        ctx.io.set_bit(Area::Input, 0, 0, *a);
        ctx.io.set_bit(Area::Input, 0, 1, *b);
        ctx.io.set_bit(Area::Input, 0, 2, *c);
        p.run(&mut ctx);
        let got = (
            p.MW2,
            ctx.io.bit(Area::Output, 0, 0),
            p.MW3,
            p.MW4,
            p.MW5,
            p.MW6,
        );
        assert_eq!(got, want, "scan {}", k + 1);
    }
}

/// `m221/listing.il`, the text listing of il-cli's `m221_listing` test,
/// through build.rs and `il!`: the inputs and hand-worked trace of that
/// test. ([Q0.0, Q0.4, Q0.5, M0, M1, Q0.7, Q0.6], C0.V, MW0, MW1, MW2.)
type ListingScan = ([bool; 7], i16, i16, i16, i16);

const LISTING_TRACE: [ListingScan; 6] = [
    ([F, F, F, F, F, F, F], 0, 0, 0, 1),
    ([F, F, F, T, F, F, F], 1, 0, 1, 2),
    ([T, F, F, T, F, F, F], 1, 0, 1, 3),
    ([F, T, T, F, T, T, F], 2, 1, 1, 4),
    ([F, T, T, T, T, T, T], 2, 2, 1, 4),
    ([F, T, F, T, T, T, T], 0, 3, 1, 4),
];

macro_rules! listing_scans {
    ($m:ident) => {{
        use il_tests::$m::M221;
        let mut ctx = Cycle::new();
        let mut p = M221::default();
        for (k, want) in LISTING_TRACE.iter().enumerate() {
            ctx.set_now(TIME::from_ms(10 * k as i64));
            ctx.io.set_byte(Area::Input, 0, INPUTS[k]);
            p.run(&mut ctx);
            let q = |j: u8| ctx.io.bit(Area::Output, 0, j);
            let got = (
                [q(0), q(4), q(5), p.M0, p.M1, q(7), q(6)],
                p.C0.V,
                p.MW0,
                p.MW1,
                p.MW2,
            );
            assert_eq!(got, *want, "{} scan {}", stringify!($m), k + 1);
        }
    }};
}

#[test]
fn the_listing_runs_through_build_rs() {
    listing_scans!(m221_listing_build);
}

#[test]
fn the_listing_runs_through_il() {
    listing_scans!(m221_listing_macro);
}
