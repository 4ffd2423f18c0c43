// Semantics: PT (a timer's input) used on a CTU counter c.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    preset : TIME;
    c : CTU;
END_VAR
    LD preset
    PT c
END_FUNCTION_BLOCK
"#);

fn main() {}
