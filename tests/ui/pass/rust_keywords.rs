// Accepted IL compiles: IL names that are Rust keywords or reserved names
// (loop, match, self, fn, crate), and a FUNCTION called `Default`.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION Default : INT
VAR_INPUT
    a : INT;
END_VAR
    LD a
    ST Default
END_FUNCTION

FUNCTION_BLOCK Names
VAR_INPUT
    go : BOOL;
    loop : BOOL;
END_VAR
VAR_OUTPUT
    match : BOOL;
    self : BOOL;
END_VAR
VAR
    fn : INT;
    crate : INT;
END_VAR
    LD go
    AND loop
    ST match
    ST self
    LD fn
    ADD crate
    Default
    ST fn
END_FUNCTION_BLOCK
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut n = Names::default();
    n.call(&mut ctx);
    assert!(!n.r#match);
}
