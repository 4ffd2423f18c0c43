// Syntax: a ';' line comment (vendor style); IEC 61131-3 comments are (* ... *).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LD x    ; copy x
    ST y
END_FUNCTION_BLOCK
"#);

fn main() {}
