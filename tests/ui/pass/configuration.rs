// A configuration with globals, externals and in-outs compiles, and the
// host drives it with the time in the cycle context.
il_macros::il!(r#"
FUNCTION_BLOCK Bump
VAR_IN_OUT n : INT; END_VAR
VAR_EXTERNAL bumps : INT; END_VAR
    LD n
    ADD 1
    ST n
    LD bumps
    ADD 1
    ST bumps
END_FUNCTION_BLOCK

PROGRAM Main
VAR_EXTERNAL bumps : INT; END_VAR
VAR b : Bump; x : INT; END_VAR
    CAL b(n := x)
END_PROGRAM

CONFIGURATION Plant
VAR_GLOBAL bumps : INT; END_VAR
TASK t (INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM m WITH t : Main;
END_CONFIGURATION
"#);

fn main() {
    let mut ctx = il_std::Cycle::new();
    let mut plant = Plant::default();
    for ms in [0, 10, 20] {
        ctx.set_now(il_std::TIME::from_ms(ms));
        plant.run(&mut ctx);
    }
    assert_eq!((plant.bumps, plant.m.x), (3, 3));
}
