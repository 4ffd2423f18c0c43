//! The guide's picture of a stopped session (`docs/debug-session.svg`) is
//! drawn from what `ilc debug` answers in the issue's scenario on
//! `examples/motor.il` (stopped on `ADD 1` in scan 3): the source with the
//! stopped line and the breakpoint, the flow-control values next to the
//! lines run, and the first scopes. The test draws it again and compares;
//! refresh it with `IL_BLESS=1 cargo test -p il-cli --test all debug::picture`.

use serde_json::json;

use super::{Dap, MOTOR, Vars};

const PICTURE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/debug-session.svg");

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// What the session shows, asked as an editor asks it.
struct Seen {
    flow: Vec<(u64, String)>,
    scopes: Vec<(String, Vars)>,
}

fn session() -> Seen {
    let mut d = Dap::start();
    d.launch(json!({"program": MOTOR, "pou": "Motor", "cycles": 6, "set": ["start=TRUE@3"]}));
    d.breakpoints(MOTOR, json!([{"line": 22}]));
    d.ok("configurationDone", json!({}));
    d.stopped();
    let (frame, _, _) = d.top();
    let flow = d.ok("flow", json!({}))["lines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            (
                l["line"].as_u64().unwrap(),
                l["cr"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    let mut scopes = Vec::new();
    for name in ["Current result", "Inputs", "Outputs"] {
        let mut vars = d.scope(frame, name);
        vars.retain(|v| v.0 != "flow");
        scopes.push((name.to_string(), vars));
    }
    d.ok("continue", json!({"threadId": 1}));
    d.event("terminated");
    d.finish();
    Seen { flow, scopes }
}

/// An editor-like view: the source at the left, the scopes at the right.
fn draw(src: &str, seen: &Seen) -> String {
    let (lh, cw) = (18, 8.4);
    let lines: Vec<&str> = src.lines().collect();
    let h = 40 + (lines.len() + 1) * lh;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1060\" height=\"{h}\" font-family=\"monospace\" font-size=\"14\">\n\
         <rect width=\"1060\" height=\"{h}\" fill=\"#1e1e1e\"/>\n\
         <text x=\"12\" y=\"22\" fill=\"#cccccc\">examples/motor.il: stopped on a breakpoint (ilc debug)</text>\n"
    );
    for (i, l) in lines.iter().enumerate() {
        let n = i as u64 + 1;
        let y = 40 + (i + 1) * lh;
        if n == 22 {
            svg += &format!(
                "<rect x=\"0\" y=\"{}\" width=\"660\" height=\"{lh}\" fill=\"#4b4b18\"/>\n<circle cx=\"10\" cy=\"{}\" r=\"5\" fill=\"#e51400\"/>\n",
                y - 14,
                y - 5
            );
        }
        svg += &format!(
            "<text x=\"22\" y=\"{y}\" fill=\"#858585\">{n:>2}</text><text x=\"52\" y=\"{y}\" fill=\"#d4d4d4\" xml:space=\"preserve\">{}</text>\n",
            esc(l)
        );
        if let Some((_, cr)) = seen.flow.iter().find(|(k, _)| *k == n) {
            let x = 60.0 + cw * l.chars().count().max(24) as f64;
            svg += &format!(
                "<text x=\"{x:.0}\" y=\"{y}\" fill=\"#6a9955\">CR = {}</text>\n",
                esc(cr)
            );
        }
    }
    let mut y = 60;
    for (name, vars) in &seen.scopes {
        svg += &format!(
            "<text x=\"680\" y=\"{y}\" fill=\"#cccccc\" font-weight=\"bold\">{}</text>\n",
            esc(name)
        );
        y += lh;
        for (n, v, t) in vars {
            svg += &format!(
                "<text x=\"696\" y=\"{y}\" fill=\"#9cdcfe\">{}</text><text x=\"800\" y=\"{y}\" fill=\"#d4d4d4\">{}</text><text x=\"940\" y=\"{y}\" fill=\"#4ec9b0\">{}</text>\n",
                esc(n),
                esc(v),
                esc(t)
            );
            y += lh;
        }
        y += 8;
    }
    svg + "</svg>\n"
}

#[test]
fn the_guides_picture_of_a_stopped_session_is_what_the_adapter_answers() {
    let src = std::fs::read_to_string(MOTOR).unwrap();
    let seen = session();
    // What the picture must show, whatever its drawing.
    assert!(
        seen.flow.contains(&(21, "0 : INT".to_string())),
        "{:?}",
        seen.flow
    );
    assert_eq!(seen.scopes[0].1[0], ("CR".into(), "0".into(), "INT".into()));
    let svg = draw(&src, &seen);
    if std::env::var_os("IL_BLESS").is_some() {
        std::fs::write(PICTURE, &svg).unwrap();
    }
    let old = std::fs::read_to_string(PICTURE).unwrap_or_default();
    assert!(
        old == svg,
        "docs/debug-session.svg is stale: refresh it with `IL_BLESS=1 cargo test -p il-cli --test all debug::picture`"
    );
}
