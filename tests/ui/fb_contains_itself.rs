// Declarations: a FUNCTION_BLOCK holding an instance of itself (infinite size).
il_macros::il!(r#"
FUNCTION_BLOCK Node
VAR
    a : BOOL;
    next : Node;
END_VAR
    LD a
    ST a
END_FUNCTION_BLOCK
"#);

fn main() {}
