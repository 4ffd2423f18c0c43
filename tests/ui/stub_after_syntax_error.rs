// Stub: a syntax error in the body (a Structured Text line); `main` uses the
// block's fields and `call`. Only the IL error may appear.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    start : BOOL;
END_VAR
VAR_OUTPUT
    done : BOOL;
END_VAR
    done := start;
END_FUNCTION_BLOCK
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut f = Fb::default();
    f.start = true;
    f.call(&mut ctx);
    let _: bool = f.done;
}
