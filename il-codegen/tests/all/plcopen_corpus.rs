//! Beremiz's first_steps PLCopen project from the shared corpus: what the
//! import says about it (its `CounterIL` run by the reference interpreter:
//! il-interp/tests/all/plcopen.rs). Skipped (with a message) when
//! ../shared is absent.

use il_codegen::Program;
use il_codegen::diag::{Severity, SourceFile};

const FILE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../shared/corpus/beremiz_beremiz_first_steps_plc.xml"
);

fn read() -> Option<SourceFile> {
    match std::fs::read_to_string(FILE) {
        Ok(t) => Some(SourceFile::new("first_steps.xml", t)),
        Err(_) => {
            eprintln!("SKIPPED: ../shared/corpus/beremiz_beremiz_first_steps_plc.xml not found");
            None
        }
    }
}

#[test]
fn only_counter_il_is_translated_and_the_rest_is_named() {
    let Some(xml) = read() else { return };
    let checked = Program::new().plcopen(xml).check();
    let input = &checked.inputs()[0];
    let diags = checked.diagnostics()[0].clone();
    assert!(
        diags.iter().all(|d| d.severity == Severity::Warning),
        "{diags:?}"
    );
    let not_il: Vec<&str> = diags
        .iter()
        .filter(|d| d.code == "IL0203")
        .map(|d| input.source().snippet(d.span))
        .collect();
    assert_eq!(
        not_il,
        [
            "AverageVal",
            "plc_prg",
            "CounterST",
            "CounterFBD",
            "CounterSFC",
            "CounterLD"
        ]
    );
    // The configuration runs plc_prg (FBD), so it is left out too.
    let cfg: Vec<_> = diags.iter().filter(|d| d.code == "IL0204").collect();
    assert_eq!(cfg.len(), 1);
    assert!(cfg[0].message.contains("`plc_prg`"), "{}", cfg[0].message);
    assert_eq!(diags.len(), 7);
}

/// Truncated and damaged copies of the project: diagnostics, never a panic,
/// and every span inside the XML text.
#[test]
fn damaged_copies_never_panic() {
    let Some(xml) = read() else { return };
    let text = xml.text.clone();
    let mut variants: Vec<String> = (0..text.len())
        .step_by(211)
        .filter(|&k| text.is_char_boundary(k))
        .map(|k| text[..k].to_string())
        .collect();
    // Damage inside the IL body: each line of CounterIL dropped in turn,
    // and characters that break IL.
    let body_start = text.find("<![CDATA[LD Reset").expect("CounterIL body");
    let body_end = body_start + text[body_start..].find("]]>").unwrap();
    let body = &text[body_start..body_end];
    for (k, line) in body.lines().enumerate() {
        if !line.trim().is_empty() {
            variants.push(text.replacen(line, "", 1));
            variants.push(text.replacen(line, &format!("{line} (*"), 1));
            variants.push(text.replacen(line, &format!("{k}: ?? {line}"), 1));
        }
    }
    for v in &variants {
        let checked = Program::new()
            .plcopen(SourceFile::new("v.xml", v.clone()))
            .check();
        let input = &checked.inputs()[0];
        for d in checked.diagnostics()[0].iter().cloned() {
            assert!(
                d.span.lo <= d.span.hi && d.span.hi as usize <= v.len(),
                "{d:?}"
            );
            for (s, _) in &d.secondary {
                assert!(s.hi as usize <= v.len());
            }
            let _ = il_codegen::diag::render(input.source(), std::slice::from_ref(&d), false);
            let _ = il_codegen::diag::to_json(input.source(), &d);
        }
        let _ = checked.emit(Default::default());
    }
}
