//! The Modicon M221's vendor blocks of il-std declared directly in IEC IL
//! (plc/m221_blocks.il), scan by scan against a hand-worked trace, through
//! build.rs, `il!` and the interpreter: the three must give the trace.

use il_codegen::ir::types::Elem;
use il_std::Cycle;

/// Inputs of one scan: r, u, i, o, w, jump, cu, cd, setb.
type In = (bool, bool, bool, bool, i16, bool, bool, bool, bool);
/// Outputs after it: step, full, (q0, q1, q2), fo, fe, lo, le, sbits, s3, sc2.
type Out = (
    i16,
    bool,
    (bool, bool, bool),
    i16,
    bool,
    i16,
    bool,
    u16,
    bool,
    bool,
);

const F: bool = false;
const T: bool = true;

/// Worked by hand from docs/semantics.md ("Modicon M221 dialect"): a 3-step
/// drum (patterns 1, 3, 4), a FIFO and a LIFO fed the same, a shift bit
/// register and a step counter on the same CU/CD.
const TRACE: [(In, Out); 9] = [
    // 1: first execution: step 0's bits are written; registers empty; %SBR0.0 set.
    (
        (F, F, F, F, 0, F, F, F, T),
        (0, F, (T, F, F), 0, T, 0, T, 1, F, F),
    ),
    // 2: U rises: step 1 (bits 1|2); 10 stored; CU rises: shift left, step 1.
    (
        (F, T, T, F, 10, F, T, F, F),
        (1, F, (T, T, F), 0, F, 0, F, 2, F, F),
    ),
    // 3: U, CU held: nothing moves.
    (
        (F, T, F, F, 0, F, T, F, F),
        (1, F, (T, T, F), 0, F, 0, F, 2, F, F),
    ),
    // 4: 20 stored.
    (
        (F, F, T, F, 20, F, F, F, F),
        (1, F, (T, T, F), 0, F, 0, F, 2, F, F),
    ),
    // 5: step 2, the last: F; retrieval: FIFO 10, LIFO 20; shift; step 2 active.
    (
        (F, T, F, T, 0, F, T, F, F),
        (2, T, (F, F, T), 10, F, 20, F, 4, F, T),
    ),
    // 6: %SBR0.0 set beside bit 2.
    (
        (F, F, F, F, 0, F, F, F, T),
        (2, T, (F, F, T), 10, F, 20, F, 5, F, T),
    ),
    // 7: past the last step: step 0; second retrieval empties both; 5 << 1 = 10 (bit 3).
    (
        (F, T, F, T, 0, F, T, F, F),
        (0, F, (T, F, F), 20, T, 10, T, 10, T, F),
    ),
    // 8: R while at step 0: no change of step, no write; CD: shift right, step 2.
    (
        (T, F, F, F, 0, F, F, T, F),
        (0, F, (T, F, F), 20, T, 10, T, 5, F, T),
    ),
    // 9: %DR0.S := 2 taken; retrieval from empty registers keeps %Rn.O.
    (
        (F, F, F, T, 0, T, F, F, F),
        (2, T, (F, F, T), 20, T, 10, T, 5, F, T),
    ),
];

macro_rules! m221_block_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::M221Objects;

            #[test]
            fn m221_blocks_follow_the_hand_worked_trace() {
                let mut ctx = Cycle::new();
                let mut f = M221Objects::default();
                for (k, &(inp, want)) in TRACE.iter().enumerate() {
                    let (r, u, i, o, w, jump, cu, cd, setb) = inp;
                    (f.r, f.u, f.i, f.o, f.w) = (r, u, i, o, w);
                    (f.jump, f.cu, f.cd, f.setb) = (jump, cu, cd, setb);
                    f.call(&mut ctx);
                    let got: Out = (
                        f.step,
                        f.full,
                        (f.q0, f.q1, f.q2),
                        f.fo,
                        f.fe,
                        f.lo,
                        f.le,
                        f.sbits,
                        f.s3,
                        f.sc2,
                    );
                    assert_eq!(got, want, "scan {}", k + 1);
                }
            }
        }
    };
}

m221_block_tests!(via_build);
m221_block_tests!(via_macro);

#[test]
fn m221_blocks_interpreted_follow_the_hand_worked_trace() {
    let src = std::fs::read_to_string("plc/m221_blocks.il").expect("read");
    let prog = il_interp::load(&il_codegen::diag::SourceFile::new("m221_blocks.il", src)).unwrap();
    let mut m = il_interp::Machine::new(&prog, "M221Objects").unwrap();
    let mut ctx = Cycle::new();
    for (k, &(inp, want)) in TRACE.iter().enumerate() {
        let (r, u, i, o, w, jump, cu, cd, setb) = inp;
        for (name, v) in [
            ("r", r),
            ("u", u),
            ("i", i),
            ("o", o),
            ("jump", jump),
            ("cu", cu),
            ("cd", cd),
            ("setb", setb),
        ] {
            m.set(name, il_interp::Value::Bool(v)).unwrap();
        }
        m.set("w", il_interp::int(w.into(), Elem::INT)).unwrap();
        m.scan(&mut ctx).unwrap();
        let b = |n: &str| m.get(n).unwrap().as_bool();
        let n = |n: &str| m.get(n).unwrap().as_i64();
        let got: Out = (
            n("step") as i16,
            b("full"),
            (b("q0"), b("q1"), b("q2")),
            n("fo") as i16,
            b("fe"),
            n("lo") as i16,
            b("le"),
            n("sbits") as u16,
            b("s3"),
            b("sc2"),
        );
        assert_eq!(got, want, "scan {}", k + 1);
    }
}
