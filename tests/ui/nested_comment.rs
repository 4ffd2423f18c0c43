// Syntax: a nested comment; IEC comments do not nest, so ' still here *)' is left over.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    (* outer (* inner *) still here *)
    LD a
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
