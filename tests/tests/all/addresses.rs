//! Direct addresses and located variables through the process image, and
//! the standard's own examples that use them (Table 51, 3.2.2, Table 53).

use il_std::{Area, Cycle};

macro_rules! address_tests {
    ($m:ident) => {
        mod $m {
            use super::*;
            use il_tests::$m::{Clause322_Parens, Located, Table51_Fan, Table53_Forms};

            /// Table 51: LD %IX1 / ANDN %MX5 / ST %QX2 — the fan runs while the
            /// button is pushed and the fan is not inhibited.
            #[test]
            fn table51_fan() {
                let mut ctx = Cycle::new();
                let mut p = Table51_Fan::default();
                for (button, inhibit, fan) in [
                    (false, false, false),
                    (true, false, true),
                    (true, true, false),
                    (false, true, false),
                ] {
                    ctx.io.set_bit(Area::Input, 0, 1, button); // %IX1 = bit 1 of byte 0
                    ctx.io.set_bit(Area::Memory, 0, 5, inhibit); // %MX5
                    p.call(&mut ctx);
                    assert_eq!(
                        ctx.io.bit(Area::Output, 0, 2),
                        fan,
                        "button {button} inhibit {inhibit}"
                    );
                }
                let names: Vec<&str> = Table51_Fan::ADDRESSES.iter().map(|l| l.address).collect();
                assert_eq!(names, ["%IX1", "%MX5", "%QX2"]);
            }

            /// 3.2.2: `AND( %IX1 OR %IX2 )` is `result := result AND (%IX1 OR %IX2)`.
            #[test]
            fn clause322_deferred_and() {
                let mut ctx = Cycle::new();
                let mut p = Clause322_Parens::default();
                for bits in 0..8u8 {
                    let (a, b, c) = (bits & 1 != 0, bits & 2 != 0, bits & 4 != 0);
                    ctx.io.set_bit(Area::Input, 0, 0, a);
                    ctx.io.set_bit(Area::Input, 1, 0, b);
                    ctx.io.set_bit(Area::Input, 2, 0, c);
                    p.call(&mut ctx);
                    assert_eq!(p.result, a && (b || c));
                }
            }

            /// Table 53: the three CAL forms count the same rising edges of %IX10.
            #[test]
            fn table53_three_forms_agree() {
                let mut ctx = Cycle::new();
                let mut p = Table53_Forms::default();
                for scan in 0..40 {
                    ctx.io.set_bit(Area::Input, 1, 2, scan % 2 == 1); // %IX10 = byte 1 bit 2
                    p.call(&mut ctx);
                    assert_eq!(p.C10.CV, p.C20.CV);
                    assert_eq!(p.C10.CV, p.C30.CV);
                    assert_eq!(p.C10.Q, p.C10.CV >= 15);
                }
                assert_eq!(p.C10.CV, 20);
                assert!(p.C30.Q);
            }

            #[test]
            fn located_variables_alias_the_image() {
                let mut ctx = Cycle::new();
                let mut p = Located::default();
                ctx.io.set_word(Area::Input, 6, (-5i16) as u16); // %IW3
                ctx.io.set_dword(Area::Memory, 4, (-10.0f32).to_bits()); // %MD1
                ctx.io.set_byte(Area::Output, 1, 255);
                p.call(&mut ctx);
                assert!(ctx.io.bit(Area::Output, 0, 7), "-5 > -10");
                assert_eq!(ctx.io.byte(Area::Output, 1), 0, "USINT wraps");
                assert!(ctx.io.bit(Area::Memory, 0, 3), "%MW0 OR 8 sets %MX0.3");
                assert_eq!(Located::ADDRESSES.len(), 5);
                assert_eq!(Located::ADDRESSES[0].byte, 6);
            }

            /// The same program bound through its typed accessors and typed
            /// IEC addresses: no byte offsets, and the values keep their
            /// IEC types (`level` is an INT, `limit` a REAL).
            #[test]
            fn typed_accessors_and_addresses() {
                use il_std::addr::{md, mx, qb, qx};
                let mut ctx = Cycle::new();
                let mut p = Located::default();
                Located::set_io_level(&mut ctx, -5);
                Located::set_io_limit(&mut ctx, -10.0);
                ctx.io.set(qb(1), 255);
                p.call(&mut ctx);
                assert!(Located::io_alarm(&ctx), "-5 > -10");
                assert_eq!(Located::io_count(&ctx), 0, "USINT wraps");
                assert!(ctx.io.get(mx(0, 3)), "%MW0 OR 8 sets %MX0.3");
                assert_eq!(Located::io_flags(&ctx), 8);
                // The accessors and the typed addresses are the same bytes.
                assert_eq!(ctx.io.get(md(1).real()), -10.0);
                assert_eq!(ctx.io.get(il_std::addr::iw(3).int()), -5);
                assert_eq!(ctx.io.get(qx(0, 7)), Located::io_alarm(&ctx));
                Located::set_io_alarm(&mut ctx, false);
                assert!(!ctx.io.bit(Area::Output, 0, 7));
            }
        }
    };
}

address_tests!(via_build);
address_tests!(via_macro);
