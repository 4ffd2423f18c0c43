// Stub: the IL has one mistake (an unknown variable `strat` in the body), and
// `main` uses the block's fields and `call`. The stub emitted next to the
// compile_error! keeps `main` type-checking: only the IL error may appear,
// no Rust error about a missing `Motor`, field or method.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Motor
VAR_INPUT
    start : BOOL;
    stop  : BOOL;
END_VAR
VAR_OUTPUT
    run : BOOL;
    starts : INT;
END_VAR
    LD   strat
    OR   run
    ANDN stop
    ST   run
END_FUNCTION_BLOCK

FUNCTION SCALE : INT
VAR_INPUT
    raw : INT;
END_VAR
    LD raw
    MUL 10
    ST SCALE
END_FUNCTION
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut m = Motor::default();
    m.start = true;
    m.call(&mut ctx);
    let running: bool = m.run;
    let n: i16 = m.starts;
    let _ = (running, n);
}
