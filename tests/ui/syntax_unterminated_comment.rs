// Syntax: a comment opened with (* and never closed.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;    (* the count
    y : INT;
END_VAR
    LD x
    ST y
END_FUNCTION_BLOCK
"#);

fn main() {}
