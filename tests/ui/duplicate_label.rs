// Semantics: the same label defined twice.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    LD a
    JMPC done
    ST q
done:
    LD FALSE
done:
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
