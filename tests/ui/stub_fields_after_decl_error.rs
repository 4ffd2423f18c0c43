// Stub: a declaration with a missing initial value (`n : INT := ;`); `main`
// uses a field declared after it. Only the IL error may appear.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    start : BOOL;
    n : INT := ;
END_VAR
VAR_OUTPUT
    done : BOOL;
END_VAR
    LD start
    ST done
END_FUNCTION_BLOCK
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut f = Fb::default();
    f.start = true;
    f.call(&mut ctx);
    let _: bool = f.done;
}
