//! The Debug Adapter Protocol's wire format: `Content-Length` framed JSON
//! messages, and the three kinds of message the adapter sends (responses,
//! error responses, events), with the `seq` numbering the specification
//! asks for. The protocol's types are the specification's JSON shapes
//! (<https://microsoft.github.io/debug-adapter-protocol/specification>),
//! built with `serde_json::json!` for the few fields used: no crate for the
//! protocol was both lean and kept up (see the guide).

use std::io::{BufRead, Write};

use serde_json::{Value, json};

/// A request body larger than this is refused unread (no editor sends one;
/// a broken client must not make the adapter allocate gigabytes).
const MAX_BODY: usize = 16 << 20;

/// One message read from the client.
#[derive(Debug)]
pub enum Incoming {
    /// A request: its `seq`, `command` and `arguments` (`null` when absent).
    Request {
        seq: i64,
        command: String,
        args: Value,
    },
    /// Something that is no request (bad JSON, a response, an event): what
    /// is wrong, and the `seq` to answer when it had one.
    Bad { seq: Option<i64>, why: String },
    /// The client closed its end.
    Eof,
}

/// Read one framed message. Headers other than `Content-Length` are skipped.
pub fn read(input: &mut impl BufRead) -> Incoming {
    let mut len = None;
    loop {
        let mut line = String::new();
        match input.read_line(&mut line) {
            Ok(0) | Err(_) => return Incoming::Eof,
            Ok(_) => {}
        }
        let line = line.trim_end_matches(['\r', '\n']);
        if line.is_empty() {
            if len.is_some() {
                break;
            }
            continue;
        }
        if let Some((k, v)) = line.split_once(':')
            && k.trim().eq_ignore_ascii_case("content-length")
        {
            len = v.trim().parse::<usize>().ok();
        }
    }
    let len = len.unwrap_or(0);
    if len > MAX_BODY {
        return Incoming::Eof;
    }
    let mut body = vec![0; len];
    if input.read_exact(&mut body).is_err() {
        return Incoming::Eof;
    }
    parse(&body)
}

/// A message body as an [`Incoming`].
pub fn parse(body: &[u8]) -> Incoming {
    let v: Value = match serde_json::from_slice(body) {
        Ok(v) => v,
        Err(e) => {
            return Incoming::Bad {
                seq: None,
                why: format!("not JSON: {e}"),
            };
        }
    };
    let seq = v.get("seq").and_then(Value::as_i64);
    match (v.get("type").and_then(Value::as_str), seq) {
        (Some("request"), Some(seq)) => match v.get("command").and_then(Value::as_str) {
            Some(c) => Incoming::Request {
                seq,
                command: c.to_string(),
                args: v.get("arguments").cloned().unwrap_or(Value::Null),
            },
            None => Incoming::Bad {
                seq: Some(seq),
                why: "a request without a `command`".into(),
            },
        },
        (Some("request"), None) => Incoming::Bad {
            seq: None,
            why: "a request without a `seq`".into(),
        },
        _ => Incoming::Bad {
            seq: None,
            why: "not a request".into(),
        },
    }
}

/// Where the adapter writes: standard output, each message framed whole.
pub struct Out {
    w: Box<dyn Write + Send>,
    seq: i64,
}

impl Out {
    pub fn new(w: Box<dyn Write + Send>) -> Out {
        Out { w, seq: 0 }
    }

    fn send(&mut self, mut msg: Value) {
        self.seq += 1;
        msg["seq"] = json!(self.seq);
        // No body is no `body` field (the schema has it an object when present).
        if let Some(m) = msg.as_object_mut()
            && m.get("body").is_some_and(Value::is_null)
        {
            m.remove("body");
        }
        let text = msg.to_string();
        // A client gone away is noticed by the reader (end of input).
        let _ = write!(self.w, "Content-Length: {}\r\n\r\n{text}", text.len());
        let _ = self.w.flush();
    }

    /// A successful response to request `seq` of `command`.
    pub fn ok(&mut self, seq: i64, command: &str, body: Value) {
        self.send(json!({
            "type": "response", "request_seq": seq, "success": true,
            "command": command, "body": body,
        }));
    }

    /// An error response: `message` is shown to the user.
    pub fn error(&mut self, seq: i64, command: &str, message: &str) {
        self.send(json!({
            "type": "response", "request_seq": seq, "success": false,
            "command": command, "message": message,
            "body": { "error": { "id": 1, "format": message, "showUser": true } },
        }));
    }

    pub fn event(&mut self, event: &str, body: Value) {
        self.send(json!({ "type": "event", "event": event, "body": body }));
    }

    /// An `output` event in `category` (`console`, `stdout`, `stderr`).
    pub fn output(&mut self, category: &str, text: &str) {
        let mut text = text.to_string();
        if !text.ends_with('\n') {
            text.push('\n');
        }
        self.event("output", json!({ "category": category, "output": text }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_read_and_bad_ones_named() {
        let body = r#"{"seq":1,"type":"request","command":"initialize"}"#;
        let text = format!("X-Other: 1\r\nContent-Length: {}\r\n\r\n{body}", body.len());
        let mut r = std::io::Cursor::new(text.as_bytes());
        assert!(
            matches!(read(&mut r), Incoming::Request { seq: 1, ref command, .. } if command == "initialize")
        );
        assert!(matches!(read(&mut r), Incoming::Eof));
        assert!(matches!(parse(b"{"), Incoming::Bad { seq: None, .. }));
        assert!(matches!(
            parse(b"{\"seq\":4,\"type\":\"request\"}"),
            Incoming::Bad { seq: Some(4), .. }
        ));
        let huge = format!("Content-Length: {}\r\n\r\n", MAX_BODY + 1);
        assert!(matches!(
            read(&mut std::io::Cursor::new(huge.as_bytes())),
            Incoming::Eof
        ));
    }
}
