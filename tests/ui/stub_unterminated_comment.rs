// Stub: an unterminated comment in the declarations swallows the rest of the
// source; `main` uses the block. Only the IL error may appear.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    start : BOOL;   (* push button
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
    f.call(&mut ctx);
}
