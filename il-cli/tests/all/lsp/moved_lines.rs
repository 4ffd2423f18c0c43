//! Edits that add or remove lines inside a POU: the server checks that POU
//! again and moves the others' results (their lines, the CR after a CAL
//! that hover names). After each edit of a seeded random sequence, what it
//! answers for the edited document (diagnostics, hover on every line,
//! inlay hints, the outline) equals what it answers for the same text
//! opened fresh in a folder of its own (a program checked from scratch).

use super::*;

const TEXT: &str = "\
FUNCTION_BLOCK Motor
VAR_INPUT start : BOOL; END_VAR
VAR_OUTPUT run : BOOL; n : INT; END_VAR
VAR t1 : TON; END_VAR
    LD start
    ST t1.IN
    CAL t1(PT := T#5s)
    LD t1.Q
    ST run
    LD n
    ADD 1
    ST n
END_FUNCTION_BLOCK

(* Between the blocks. *)
FUNCTION_BLOCK Pump
VAR_INPUT en : BOOL; END_VAR
VAR_OUTPUT q : BOOL; level : INT; END_VAR
VAR m : Motor; END_VAR
    CAL m(start := en)
    LD m.run
    ST q
    CAL m(start := q)
    JMPC done
    LD level
    ADD 2
    ST level
done:
    LD level
    ST level
END_FUNCTION_BLOCK

PROGRAM Main
VAR p : Pump; x : INT; b : BOOL; END_VAR
    CAL p(en := TRUE)
    LD p.level
    ST x
    LD b
    JMPC mixed
    LD x
mixed:
    ST x
    CAL p(en := b)
    ST b
END_PROGRAM
";

/// Instruction lines an editor's user adds (some with errors).
const LINES: &[&str] = &[
    "    LD   x\n",
    "    ADD  nosuch\n",
    "    LD   1\n",
    "    ST   level\n",
    "    CAL  t1(PT := T#1s)\n",
    "\n",
    "    (* a note *)\n",
    "    ST   run\n",
];

/// What the server says of document `uri` with text `text`: its
/// diagnostics, hover at the first word of every line, inlay hints and
/// outline, with `uri` written as `URI`.
fn answers(c: &mut Client, uri: &str, text: &str, diagnostics: Vec<Value>) -> Vec<String> {
    let mut out = vec![serde_json::to_string(&diagnostics).unwrap()];
    for (n, line) in text.lines().enumerate() {
        let col = line.len() - line.trim_start().len();
        let h = c.result("textDocument/hover", pos(uri, n, col));
        out.push(format!("line {n}: {}", hover_text(&h)));
    }
    let lines = text.lines().count();
    out.push(
        c.result(
            "textDocument/inlayHint",
            json!({"textDocument": {"uri": uri}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": lines, "character": 0}}}),
        )
        .to_string(),
    );
    out.push(
        c.result(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": uri}}),
        )
        .to_string(),
    );
    out.into_iter().map(|s| s.replace(uri, "URI")).collect()
}

#[test]
fn after_lines_added_and_removed_the_server_answers_as_for_a_fresh_text() {
    let dir = temp_dir("moved-lines");
    let m = uri(&dir.join("edited/m.il"));
    let mut text = TEXT.to_string();
    let mut c = Client::start(&[]);
    c.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    // Messages that name lines: a CR used after a CAL (twice), and paths
    // into `mixed` that disagree.
    assert_eq!(c.diagnostics_for(&m).len(), 3);
    let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
    let mut rand = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as usize
    };
    let mut shown_after_cal = 0;
    for version in 2..32 {
        let lines: Vec<&str> = text.split_inclusive('\n').collect();
        // A line inside a body (not a POU's first four lines or its END).
        let bodies: Vec<usize> = (0..lines.len())
            .filter(|&n| {
                lines[n].starts_with("    ")
                    && !lines[n].contains("END_")
                    && (n < 4 || !lines[n - 4].starts_with("FUNCTION_BLOCK"))
            })
            .collect();
        let n = bodies[rand(bodies.len())];
        let (range, new) = if rand(2) == 0 || lines.len() < 40 {
            let add = LINES[rand(LINES.len())];
            let at = json!({"line": n, "character": 0});
            (json!({"start": at, "end": at}), add)
        } else {
            let range = json!({"start": {"line": n, "character": 0}, "end": {"line": n + 1, "character": 0}});
            (range, "")
        };
        let start: usize = lines[..n].iter().map(|l| l.len()).sum();
        let end = if new.is_empty() {
            start + lines[n].len()
        } else {
            start
        };
        text.replace_range(start..end, new);
        c.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": m, "version": version}, "contentChanges": [{"range": range, "text": new}]}),
        );
        let published = c.diagnostics_for(&m);
        let edited = answers(&mut c, &m, &text, published);
        // The same text in a folder of its own: checked from scratch.
        let f = uri(&dir.join(format!("fresh{version}/m.il")));
        c.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": f, "languageId": "il", "version": 1, "text": text}}),
        );
        let published = c.diagnostics_for(&f);
        let fresh = answers(&mut c, &f, &text, published);
        c.notify("textDocument/didClose", json!({"textDocument": {"uri": f}}));
        for (a, b) in edited.iter().zip(&fresh) {
            assert_eq!(a, b, "edit {version}:\n{text}");
        }
        assert_eq!(edited.len(), fresh.len());
        shown_after_cal += edited
            .iter()
            .filter(|h| h.contains("after CAL on line"))
            .count();
    }
    // The CR after a CAL names its line: the moved lines were compared.
    assert!(shown_after_cal > 30, "{shown_after_cal}");
    c.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
