//! The `Content-Length` framing of JSON messages that LSP and DAP share,
//! for tests and benchmarks that drive `ilc lsp` / `ilc debug` over stdio
//! as an editor does.

use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::sync::mpsc::{Receiver, channel};

/// Write one message.
pub fn send(w: &mut impl Write, msg: &Value) -> std::io::Result<()> {
    let body = msg.to_string();
    write!(w, "Content-Length: {}\r\n\r\n{body}", body.len())?;
    w.flush()
}

/// Read one message; `None` at the end of the stream (or on a broken one).
pub fn read(r: &mut impl BufRead) -> Option<Value> {
    let mut len = None;
    loop {
        let mut line = String::new();
        if r.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(v) = line.strip_prefix("Content-Length:") {
            len = v.trim().parse::<usize>().ok();
        }
    }
    let mut body = vec![0; len.expect("a Content-Length header")];
    r.read_exact(&mut body).ok()?;
    Some(serde_json::from_slice(&body).expect("a JSON message"))
}

/// Every message of `stream`, read on a thread of its own, so that a test
/// can wait for one with a timeout.
pub fn reader(stream: impl Read + Send + 'static) -> Receiver<Value> {
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        let mut r = BufReader::new(stream);
        while let Some(v) = read(&mut r) {
            if tx.send(v).is_err() {
                return;
            }
        }
    });
    rx
}
