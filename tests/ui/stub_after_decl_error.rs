// Stub: the mistake is in the declarations (unknown type `TONN` for `delay`);
// `main` uses the block's other fields and `call`. Only the IL error may
// appear, no Rust error about `Fb`, its fields or `call`.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    start : BOOL;
END_VAR
VAR_OUTPUT
    done : BOOL;
END_VAR
VAR
    delay : TONN;
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
