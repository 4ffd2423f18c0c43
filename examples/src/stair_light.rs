//! A staircase light, written inline with `il!`: each press of the button
//! (R_TRIG) keeps the lamp on for 10 s after it (TOF); during the last 2 s
//! a warning light tells people to press again.

use crate::{SCAN, Timeline};
use il_std::Cycle;

il_macros::il!(
    r#"
(* Staircase light: a TOF holds the lamp on for 10 s after the last press. *)
FUNCTION_BLOCK StairLight
VAR_INPUT
    button : BOOL;
END_VAR
VAR_OUTPUT
    lamp : BOOL;
    warn : BOOL;       (* the lamp goes off soon: press again *)
    left : TIME;       (* time until the lamp goes off *)
END_VAR
VAR
    press : R_TRIG;
    hold  : TOF;
END_VAR
    LD   button
    CLK  press              (* a held button counts once *)
    CAL  hold(IN := press.Q, PT := T#10s)
    LD   hold.Q
    ST   lamp
    LD   T#10s
    SUB  hold.ET
    ST   left
    LE   T#2s
    AND  hold.Q
    ST   warn
END_FUNCTION_BLOCK
"#
);

/// A press, a press during the warning that extends the light, a long press
/// that counts once.
pub fn run() -> Timeline {
    let mut tl = Timeline::new(
        "stair light: on for 10 s after each press (TOF), warning in the last 2 s",
        &["button"],
        &["lamp", "warn"],
    );
    let mut ctx = Cycle::new();
    let mut s = StairLight::default();
    while ctx.now().as_ms() <= 26_000 {
        let note = match ctx.now().as_ms() {
            1_000 => {
                s.button = true;
                "press"
            }
            1_200 => {
                s.button = false;
                ""
            }
            10_000 => {
                s.button = true;
                "press again during the warning"
            }
            10_200 => {
                s.button = false;
                ""
            }
            12_000 => {
                s.button = true;
                "hold the button for 3 s: one press"
            }
            15_000 => {
                s.button = false;
                ""
            }
            _ => "",
        };
        s.call(&mut ctx);
        tl.record(ctx.now(), &[&s.button, &s.lamp, &s.warn], note);
        ctx.advance(SCAN);
    }
    tl
}
