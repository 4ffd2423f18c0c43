//! Every example of the three seed documents (spec/seeds) with its documented
//! result (plc/seeds.il).

use il_std::Cycle;

macro_rules! seed_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::*;

            /// CODESYS (002): `LD 2 / MUL 2 / ADD 3 / ST Erg` gives Erg = 7, and
            /// `LD 2 / MUL( 2 / ADD 3 / ) / ST Erg` gives Erg = 10.
            #[test]
            fn codesys_parentheses_7_and_10() {
                let mut ctx = Cycle::new();
                let mut p = CodesysParens::default();
                p.call(&mut ctx);
                assert_eq!(p.Erg, 7);
                assert_eq!(p.Erg2, 10);
            }

            /// CODESYS (002) modifiers example: whichever way the JMPC goes, the
            /// code after `label:` leaves ERG = BOOL2.
            #[test]
            fn codesys_modifiers_example() {
                let mut ctx = Cycle::new();
                for b1 in [false, true] {
                    for b2 in [false, true] {
                        let mut f = CodesysModifiers::default();
                        f.BOOL1 = b1;
                        f.BOOL2 = b2;
                        f.call(&mut ctx);
                        assert_eq!(f.took_jump, !b1, "TRUE ANDN BOOL1");
                        assert_eq!(f.ERG, b2, "BOOL1={b1} BOOL2={b2}");
                    }
                }
            }

            /// CODESYS (002) first example: `LD 17 / ST lint / GE 5 / JMPC next /
            /// LD idword / EQ istruct.sdword / STN test / next:`. 17 >= 5, so
            /// the jump is taken and `test` is untouched; with 3 it is not, and
            /// test = NOT (idword = sdword).
            #[test]
            fn codesys_first_example() {
                let mut ctx = Cycle::new();
                let mut f = CodesysFirst::default();
                f.idword = 1;
                f.sdword = 2;
                f.call(&mut ctx);
                assert_eq!(f.lint, 17);
                assert!(!f.test, "jumped over STN test");
                f.start = 3;
                f.call(&mut ctx);
                assert_eq!(f.lint, 3);
                assert!(f.test, "STN of (1 = 2)");
                f.sdword = 1;
                f.call(&mut ctx);
                assert!(!f.test);
            }

            /// KAS-IDE (001): `BEGIN_IL / LD var1 / ST var2 / END_IL` copies var1
            /// to var2; the comment example `LD a / ST b (* ... *)` copies a to b.
            #[test]
            fn kas_ide_begin_il_example() {
                let mut ctx = Cycle::new();
                let mut f = KasIde::default();
                f.var1 = 1234;
                f.a = true;
                f.call(&mut ctx);
                assert_eq!(f.var2, 1234);
                assert!(f.b);
            }

            /// IEC 61131-3 3.2.2: `AND( %IX1 / OR %IX2 / )` is
            /// result := result AND (%IX1 OR %IX2); Table 51: START: LD %IX1 /
            /// ANDN %MX5 / ST %QX2 (direct addresses replaced by variables).
            #[test]
            fn iec_and_paren_and_table51() {
                let mut ctx = Cycle::new();
                for bits in 0..32u8 {
                    let mut f = IecExamples::default();
                    f.start_in = bits & 1 != 0;
                    f.ix1 = bits & 2 != 0;
                    f.ix2 = bits & 4 != 0;
                    f.push_button = bits & 8 != 0;
                    f.inhibited = bits & 16 != 0;
                    f.call(&mut ctx);
                    assert_eq!(f.result, f.start_in && (f.ix1 || f.ix2));
                    assert_eq!(f.fan_on, f.push_button && !f.inhibited);
                }
            }
        }
    };
}

seed_tests!(via_build);
seed_tests!(via_macro);
