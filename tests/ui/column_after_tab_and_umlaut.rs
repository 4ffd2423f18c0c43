// Position: a tab-indented line and a non-ASCII comment before the mistake
// (an unknown variable); the column must count characters, tabs as one.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
	a : BOOL;	(* Förderband läuft *)
	q : BOOL;
END_VAR
	(* Schütz — Ausgang *)
	LD a
	ST qq
END_FUNCTION_BLOCK
"#);

fn main() {}
