//! The interfaces of the standard function blocks: inputs, outputs and
//! their types, one table for the checker, the emitter and the interpreter.

use super::*;

/// One input or output of a standard function block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FbParam {
    /// IEC name, which is also the Rust field name of the block (`IN`, `PT`, `Q`, `ET` ...).
    pub name: &'static str,
    /// Its type.
    pub ty: Elem,
}

/// The interface of one standard function block of this crate ([`TON`](crate::TON) ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FbSignature {
    /// IEC name, which is also the Rust type name at the crate root.
    pub name: &'static str,
    /// Inputs, in declaration order.
    pub inputs: &'static [FbParam],
    /// Outputs, in declaration order.
    pub outputs: &'static [FbParam],
}

/// The standard function blocks as one list, for tables and code generated from it: calls
/// `$callback! { NAME (INPUT: TYPE, ...) -> (OUTPUT: TYPE, ...); ... }` with every block, in
/// the order of [`FB_SIGNATURES`]. Types are [`Elem`] names; fields are the blocks' field
/// names. [`FB_SIGNATURES`] is built from it, and a test proves every block and field exists
/// with its type; so are the crate root's re-exports of the blocks, their `FunctionBlock`
/// and `trace::Visit` impls (the `runtime` feature), and the interpreter's instances,
/// which reach the fields by name. Adding a block is its struct and one line here.
#[macro_export]
macro_rules! std_function_blocks {
    ($callback:ident) => {
        $callback! {
            SR (S1: BOOL, R: BOOL) -> (Q1: BOOL);
            RS (S: BOOL, R1: BOOL) -> (Q1: BOOL);
            R_TRIG (CLK: BOOL) -> (Q: BOOL);
            F_TRIG (CLK: BOOL) -> (Q: BOOL);
            CTU (CU: BOOL, R: BOOL, PV: INT) -> (Q: BOOL, CV: INT);
            CTU_INT (CU: BOOL, R: BOOL, PV: INT) -> (Q: BOOL, CV: INT);
            CTU_DINT (CU: BOOL, R: BOOL, PV: DINT) -> (Q: BOOL, CV: DINT);
            CTU_LINT (CU: BOOL, R: BOOL, PV: LINT) -> (Q: BOOL, CV: LINT);
            CTU_UDINT (CU: BOOL, R: BOOL, PV: UDINT) -> (Q: BOOL, CV: UDINT);
            CTU_ULINT (CU: BOOL, R: BOOL, PV: ULINT) -> (Q: BOOL, CV: ULINT);
            CTD (CD: BOOL, LD: BOOL, PV: INT) -> (Q: BOOL, CV: INT);
            CTD_INT (CD: BOOL, LD: BOOL, PV: INT) -> (Q: BOOL, CV: INT);
            CTD_DINT (CD: BOOL, LD: BOOL, PV: DINT) -> (Q: BOOL, CV: DINT);
            CTD_LINT (CD: BOOL, LD: BOOL, PV: LINT) -> (Q: BOOL, CV: LINT);
            CTD_UDINT (CD: BOOL, LD: BOOL, PV: UDINT) -> (Q: BOOL, CV: UDINT);
            CTD_ULINT (CD: BOOL, LD: BOOL, PV: ULINT) -> (Q: BOOL, CV: ULINT);
            CTUD (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: INT) -> (QU: BOOL, QD: BOOL, CV: INT);
            CTUD_INT (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: INT) -> (QU: BOOL, QD: BOOL, CV: INT);
            CTUD_DINT (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: DINT) -> (QU: BOOL, QD: BOOL, CV: DINT);
            CTUD_LINT (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: LINT) -> (QU: BOOL, QD: BOOL, CV: LINT);
            CTUD_UDINT (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: UDINT) -> (QU: BOOL, QD: BOOL, CV: UDINT);
            CTUD_ULINT (CU: BOOL, CD: BOOL, R: BOOL, LD: BOOL, PV: ULINT) -> (QU: BOOL, QD: BOOL, CV: ULINT);
            TP (IN: BOOL, PT: TIME) -> (Q: BOOL, ET: TIME);
            TON (IN: BOOL, PT: TIME) -> (Q: BOOL, ET: TIME);
            TOF (IN: BOOL, PT: TIME) -> (Q: BOOL, ET: TIME);
            RTC (IN: BOOL, PDT: DT) -> (Q: BOOL, CDT: DT);
            M221_C (R: BOOL, S: BOOL, CU: BOOL, CD: BOOL, P: INT) -> (E: BOOL, D: BOOL, F: BOOL, V: INT);
            M221_DR (R: BOOL, U: BOOL, S: INT, STEPS: INT, P0: WORD, P1: WORD, P2: WORD, P3: WORD, P4: WORD, P5: WORD, P6: WORD, P7: WORD) -> (F: BOOL, CTRL: WORD, UPD: BOOL);
            M221_FIFO (R: BOOL, I: BOOL, O: BOOL, IW: INT, OW: INT) -> (E: BOOL, F: BOOL);
            M221_LIFO (R: BOOL, I: BOOL, O: BOOL, IW: INT, OW: INT) -> (E: BOOL, F: BOOL);
            M221_SBR (R: BOOL, CU: BOOL, CD: BOOL, X: WORD) -> ();
            M221_SC (R: BOOL, CU: BOOL, CD: BOOL, X0: WORD, X1: WORD, X2: WORD, X3: WORD, X4: WORD, X5: WORD, X6: WORD, X7: WORD, X8: WORD, X9: WORD, X10: WORD, X11: WORD, X12: WORD, X13: WORD, X14: WORD, X15: WORD) -> ();
            M221_SYS () -> (S0: BOOL, S4: BOOL, S5: BOOL, S6: BOOL, S7: BOOL, S13: BOOL);
        }
    };
}

macro_rules! build_fb_table {
    ($( $name:ident ( $( $i:ident : $it:ident ),* ) -> ( $( $o:ident : $ot:ident ),* ); )*) => {
        /// Every standard function block of this crate: its inputs and outputs.
        pub static FB_SIGNATURES: &[FbSignature] = &[
            $( FbSignature {
                name: stringify!($name),
                inputs: &[ $( FbParam { name: stringify!($i), ty: Elem::$it } ),* ],
                outputs: &[ $( FbParam { name: stringify!($o), ty: Elem::$ot } ),* ],
            }, )*
        ];

        /// Compile-time proof that every entry names a real block whose fields have the
        /// listed types.
        #[cfg(all(test, feature = "runtime"))]
        #[allow(dead_code, non_snake_case)]
        mod fb_fields_exist {
            $( fn $name(b: &crate::$name) {
                $( let _: crate::$it = b.$i; )*
                $( let _: crate::$ot = b.$o; )*
            } )*
        }
    };
}

std_function_blocks!(build_fb_table);

/// The interface of the standard function block `name` (case-insensitive).
pub fn lookup_fb(name: &str) -> Option<&'static FbSignature> {
    FB_SIGNATURES
        .iter()
        .find(|f| f.name.eq_ignore_ascii_case(name))
}
