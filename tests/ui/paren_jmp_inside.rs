// Parentheses: a JMP inside a deferred AND( ... ).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    c : BOOL;
    q : BOOL;
END_VAR
    LD a
    AND(
        LD b
        JMP done
        OR c
    )
done:
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
