//! Edits that add or remove lines inside a POU: the server checks that POU
//! again and moves the others' results (their lines, the CR after a CAL
//! that hover names). After each edit of a seeded random sequence, what it
//! answers for the edited document (diagnostics, hover on every line,
//! inlay hints, the outline) equals what it answers for the same text
//! opened fresh in another server (a program checked from scratch),
//! and most edits moved the server's index instead of building it.

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

/// The diagnostics of `uri` once the server has checked the last edit:
/// those it published since `last`, or `last` if it published none (an
/// edit that left them as they were). A request makes it check first.
fn current(c: &mut Client, uri: &str, last: Vec<Value>) -> Vec<Value> {
    c.result(
        "textDocument/documentSymbol",
        json!({"textDocument": {"uri": uri}}),
    );
    let mut now = last;
    c.notes.retain(|n| {
        let this = n["method"] == "textDocument/publishDiagnostics" && n["params"]["uri"] == uri;
        if this {
            now = n["params"]["diagnostics"].as_array().unwrap().clone();
        }
        !this
    });
    now
}

#[test]
fn after_lines_added_and_removed_the_server_answers_as_for_a_fresh_text() {
    let dir = temp_dir("moved-lines");
    let m = uri(&dir.join("edited/m.il"));
    let mut text = TEXT.to_string();
    // The server logs where each check's time went (`moved 1`: the index
    // of the edited program was moved, not built).
    let mut c = Client::start(&[("ILC_LSP_TIMES", "1")]);
    c.initialize(&dir, json!({}));
    // Another server: each text opened fresh, in a folder of its own.
    let mut other = Client::start(&[]);
    other.initialize(&dir, json!({}));
    c.notify(
        "textDocument/didOpen",
        json!({"textDocument": {"uri": m, "languageId": "il", "version": 1, "text": text}}),
    );
    // Messages that name lines: a CR used after a CAL (twice), and paths
    // into `mixed` that disagree.
    let mut shown = c.diagnostics_for(&m);
    assert_eq!(shown.len(), 3);
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
        // A line of a body: an instruction (indented) or a label.
        let label = |l: &str| !l.starts_with(' ') && l.trim_end().ends_with(':');
        let body = |l: &str| (l.starts_with("    ") || label(l)) && !l.contains("END_");
        let bodies: Vec<usize> = (0..lines.len()).filter(|&n| body(lines[n])).collect();
        let n = bodies[rand(bodies.len())];
        let start: usize = lines[..n].iter().map(|l| l.len()).sum();
        // Replace lines `n..n + k` with `new`.
        let (k, new) = match rand(3) {
            0 => (0, LINES[rand(LINES.len())].to_string()),
            1 if lines.len() > 40 => (1, String::new()),
            // Swap two lines (a label moves among instructions).
            _ if lines.get(n + 1).is_some_and(|l| body(l)) => {
                (2, format!("{}{}", lines[n + 1], lines[n]))
            }
            _ => (0, LINES[rand(LINES.len())].to_string()),
        };
        let end = start + lines[n..n + k].iter().map(|l| l.len()).sum::<usize>();
        let range =
            json!({"start": {"line": n, "character": 0}, "end": {"line": n + k, "character": 0}});
        text.replace_range(start..end, &new);
        c.notify(
            "textDocument/didChange",
            json!({"textDocument": {"uri": m, "version": version}, "contentChanges": [{"range": range, "text": new}]}),
        );
        shown = current(&mut c, &m, shown);
        let edited = answers(&mut c, &m, &text, shown.clone());
        // The same text in a folder of its own: checked from scratch.
        let f = uri(&dir.join(format!("fresh{version}/m.il")));
        other.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": f, "languageId": "il", "version": 1, "text": text}}),
        );
        let published = other.diagnostics_for(&f);
        let fresh = answers(&mut other, &f, &text, published);
        other.notify("textDocument/didClose", json!({"textDocument": {"uri": f}}));
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
    let log = c.finish_with_log();
    let moved = log.matches(" moved 1 ").count();
    assert!(moved >= 15, "the index moved {moved} times of 30:\n{log}");
    other.finish();
    let _ = std::fs::remove_dir_all(&dir);
}
