//! Deferred operations `OP(` ... `)` (plc/parens.il) through both front ends.

use il_std::Cycle;

macro_rules! parens_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{ParensArith, ParensBool};

            #[test]
            fn boolean_parentheses_all_inputs() {
                let mut ctx = Cycle::new();
                for bits in 0..16u8 {
                    let (a, b, c, d) = (bits & 1 != 0, bits & 2 != 0, bits & 4 != 0, bits & 8 != 0);
                    let mut f = ParensBool::default();
                    f.a = a;
                    f.b = b;
                    f.c = c;
                    f.d = d;
                    f.call(&mut ctx);
                    let case = format!("a={a} b={b} c={c} d={d}");
                    assert_eq!(f.short_and, a && (b || c), "AND( short {case}");
                    assert_eq!(f.long_and, a && (b || c), "AND( long {case}");
                    assert_eq!(f.andn_par, a && !(b || c), "ANDN( {case}");
                    assert_eq!(f.orn_par, a || !(b && c), "ORN( {case}");
                    assert_eq!(f.xor_par, a ^ (b && c), "XOR( {case}");
                    assert_eq!(f.nested3, a && (b || (c && !d)), "3 deep short {case}");
                    assert_eq!(
                        f.nested3_long,
                        a || (b && (c ^ (d || a))),
                        "3 deep long {case}"
                    );
                    assert_eq!(f.amp_par, a && (b ^ c), "&( {case}");
                    assert_eq!(f.xorn_par, a ^ !(b || c), "XORN( {case}");
                    assert_eq!(f.ampn_par, a && !(b && c), "&N( {case}");
                }
            }

            #[test]
            fn arithmetic_and_comparison_parentheses() {
                let mut ctx = Cycle::new();
                for (x, y, z) in [
                    (2i16, 2i16, 3i16),
                    (20, 3, 4),
                    (-9, 5, -2),
                    (7, 7, 0),
                    (4, 2, 8),
                ] {
                    let mut f = ParensArith::default();
                    f.x = x;
                    f.y = y;
                    f.z = z;
                    f.call(&mut ctx);
                    let case = format!("x={x} y={y} z={z}");
                    assert_eq!(f.erg_plain, x * y + z, "no parens {case}");
                    assert_eq!(f.erg_par, x * (y + z), "MUL( {case}");
                    assert_eq!(f.sub_par, x - (y - z), "SUB( {case}");
                    let s = y + z;
                    assert_eq!(f.div_par, if s == 0 { 0 } else { x / s }, "DIV( {case}");
                    assert_eq!(f.mod_par, if s == 0 { 0 } else { x % s }, "MOD( {case}");
                    assert_eq!(f.nest_arith, x - (y * (z + (x - 1))), "nested {case}");
                    assert_eq!(f.gt_par, x > y + z, "GT( {case}");
                    assert_eq!(f.eq_par, x == y * z, "EQ( {case}");
                    assert_eq!(f.le_par, x <= y - z, "LE( {case}");
                    assert_eq!(f.ge_par, x >= y - z, "GE( {case}");
                    assert_eq!(f.lt_par, x < y - z, "LT( {case}");
                    assert_eq!(f.ne_par, x != y - z, "NE( {case}");
                    assert_eq!(f.mixed, x > y && y + z == 10, "GT then AND( {case}");
                    assert_eq!(f.long_add, x + y * z, "ADD( long {case}");
                }
            }
        }
    };
}

parens_tests!(via_build);
parens_tests!(via_macro);
