// `il!(..., serde)` derives serde's traits on the generated types.
il_macros::il!(r#"
TYPE Mode : (Idle, Run); END_TYPE
FUNCTION_BLOCK Counter
VAR RETAIN n : DINT; END_VAR
VAR mode : Mode; END_VAR
    LD n
    ADD 1
    ST n
END_FUNCTION_BLOCK
"#, serde);

fn is_serde<T: serde::Serialize + for<'de> serde::Deserialize<'de>>() {}

fn main() {
    is_serde::<Mode>();
    is_serde::<Counter>();
    is_serde::<Counter__Retain>();
}
