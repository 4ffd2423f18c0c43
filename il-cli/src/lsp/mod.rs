//! `ilc lsp`: a Language Server Protocol server over stdio (the
//! `lsp-server` crate does the JSON-RPC framing, `lsp-types` the messages).
//!
//! One thread: notifications update the documents, and the program is
//! re-checked once the queue holds no more of them (a burst of edits costs
//! one check), or before a request is answered, so every answer sees the
//! latest text. A panic in a handler is caught, logged to stderr and
//! answered with an error; the server goes on.

mod completion;
mod convert;
mod diagnostics;
mod formatting;
mod hover;
mod index;
mod inlay;
mod navigation;
mod refactor;
mod semantic;
mod signature;
mod symbols;
mod workspace;

use std::error::Error;
use std::panic::{AssertUnwindSafe, catch_unwind};

use crossbeam_channel::TryRecvError;
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{self as note, Notification as _};
use lsp_types::request::{self as req, Request as _};
use lsp_types::{
    CompletionOptions, HoverProviderCapability, InitializeParams, OneOf, RenameOptions,
    ServerCapabilities, TextDocumentSyncCapability, TextDocumentSyncKind, WorkDoneProgressOptions,
};
use serde_json::Value;

use workspace::Workspace;

type Fallible<T> = Result<T, Box<dyn Error + Send + Sync>>;

/// Serve on stdin/stdout until the client says `exit`. Returns the exit
/// status (0 after `shutdown` then `exit`).
/// `encoding`: `ilc --encoding`, which the client's initialization option
/// `encoding` overrides.
pub fn run(encoding: il_codegen::read::Encoding) -> u8 {
    let (conn, io) = Connection::stdio();
    let status = match serve(&conn, encoding) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("ilc lsp: {e}");
            1
        }
    };
    drop(conn);
    if let Err(e) = io.join() {
        eprintln!("ilc lsp: {e}");
    }
    status
}

fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Kind(
            TextDocumentSyncKind::INCREMENTAL,
        )),
        hover_provider: Some(HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        document_highlight_provider: Some(OneOf::Left(true)),
        rename_provider: Some(OneOf::Right(RenameOptions {
            prepare_provider: Some(true),
            work_done_progress_options: WorkDoneProgressOptions::default(),
        })),
        document_symbol_provider: Some(OneOf::Left(true)),
        workspace_symbol_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec![".".into(), " ".into(), "(".into(), ",".into()]),
            ..Default::default()
        }),
        inlay_hint_provider: Some(OneOf::Left(true)),
        document_formatting_provider: Some(OneOf::Left(true)),
        code_action_provider: Some(lsp_types::CodeActionProviderCapability::Simple(true)),
        signature_help_provider: Some(lsp_types::SignatureHelpOptions {
            trigger_characters: Some(vec!["(".into(), ",".into(), " ".into()]),
            retrigger_characters: None,
            work_done_progress_options: Default::default(),
        }),
        semantic_tokens_provider: Some(
            lsp_types::SemanticTokensServerCapabilities::SemanticTokensOptions(
                lsp_types::SemanticTokensOptions {
                    legend: semantic::legend(),
                    full: Some(lsp_types::SemanticTokensFullOptions::Bool(true)),
                    range: None,
                    work_done_progress_options: Default::default(),
                },
            ),
        ),
        document_range_formatting_provider: Some(OneOf::Left(true)),
        ..Default::default()
    }
}

fn serve(conn: &Connection, encoding: il_codegen::read::Encoding) -> Fallible<()> {
    let init = conn.initialize(serde_json::to_value(capabilities())?)?;
    let mut ws = Workspace::default();
    ws.settings.encoding = encoding;
    if let Some(opts) = init.get("initializationOptions")
        && let Err(e) = ws.settings.update(opts)
    {
        // The editor shows the server's stderr in its log.
        eprintln!("ilc lsp: initializationOptions: {e}");
    }
    ws.settings.hint_refresh = init
        .pointer("/capabilities/workspace/inlayHint/refreshSupport")
        .and_then(serde_json::Value::as_bool)
        .unwrap_or(false);
    if let Ok(params) = serde_json::from_value::<InitializeParams>(init) {
        let mut roots: Vec<lsp_types::Uri> = params
            .workspace_folders
            .unwrap_or_default()
            .into_iter()
            .map(|f| f.uri)
            .collect();
        #[allow(deprecated)] // older clients send only rootUri
        if roots.is_empty()
            && let Some(u) = params.root_uri
        {
            roots.push(u);
        }
        for r in roots {
            if r.as_str().starts_with("file:") {
                ws.scan(std::path::Path::new(&convert::uri_to_name(&r)));
            }
        }
    }
    let mut dirty = true;
    loop {
        let msg = if dirty {
            match conn.receiver.try_recv() {
                Ok(m) => m,
                Err(TryRecvError::Empty) => {
                    recheck(conn, &mut ws)?;
                    dirty = false;
                    continue;
                }
                Err(TryRecvError::Disconnected) => return Ok(()),
            }
        } else {
            match conn.receiver.recv() {
                Ok(m) => m,
                Err(_) => return Ok(()),
            }
        };
        match msg {
            Message::Request(r) => {
                if conn.handle_shutdown(&r)? {
                    return Ok(());
                }
                if dirty {
                    recheck(conn, &mut ws)?;
                    dirty = false;
                }
                let method = r.method.clone();
                let id = r.id.clone();
                let resp =
                    catch_unwind(AssertUnwindSafe(|| request(&ws, r))).unwrap_or_else(|_| {
                        eprintln!(
                            "ilc lsp: the handler of `{method}` panicked; the server goes on"
                        );
                        Response::new_err(
                            id,
                            ErrorCode::InternalError as i32,
                            format!("internal error while answering `{method}`"),
                        )
                    });
                conn.sender.send(resp.into())?;
            }
            Message::Notification(n) => {
                if n.method == note::Exit::METHOD {
                    return Ok(());
                }
                let method = n.method.clone();
                match catch_unwind(AssertUnwindSafe(|| notification(conn, &mut ws, n))) {
                    Ok(changed) => dirty |= changed?,
                    Err(_) => {
                        eprintln!("ilc lsp: the handler of `{method}` panicked; the server goes on")
                    }
                }
            }
            Message::Response(_) => {}
        }
    }
}

/// Check again and publish the diagnostics that changed. A panic in the
/// checker is caught: the last analysis stays.
fn recheck(conn: &Connection, ws: &mut Workspace) -> Fallible<()> {
    let start = std::time::Instant::now();
    if catch_unwind(AssertUnwindSafe(|| ws.check())).is_err() {
        eprintln!("ilc lsp: the check panicked; keeping the last results");
        return Ok(());
    }
    let checked = start.elapsed();
    for (uri, diagnostics) in ws.take_changed_diagnostics() {
        publish(conn, uri, diagnostics)?;
    }
    let published = start.elapsed();
    ws.release();
    if std::env::var_os("ILC_LSP_TIMES").is_some() {
        // Where an edit's time goes, for BENCHMARKS.md (`lsp_latency --times`).
        let ms = |d: std::time::Duration| d.as_secs_f64() * 1e3;
        let t = &ws.times;
        eprintln!(
            "ilc lsp: times: pous {} moved {} parse {:.1} check {:.1} index {:.1} lines {:.1} publish {:.1} release {:.1} ms",
            t.pous,
            t.moved,
            ms(t.parse),
            ms(t.check),
            ms(t.index),
            ms(t.lines),
            ms(published - checked),
            ms(start.elapsed() - published)
        );
    }
    Ok(())
}

fn publish(
    conn: &Connection,
    uri: lsp_types::Uri,
    diagnostics: Vec<lsp_types::Diagnostic>,
) -> Fallible<()> {
    let params = lsp_types::PublishDiagnosticsParams {
        uri,
        diagnostics,
        version: None,
    };
    conn.sender.send(Message::Notification(Notification::new(
        note::PublishDiagnostics::METHOD.to_string(),
        params,
    )))?;
    Ok(())
}

/// Apply a notification; returns whether the documents changed.
fn notification(conn: &Connection, ws: &mut Workspace, n: Notification) -> Fallible<bool> {
    match n.method.as_str() {
        note::DidOpenTextDocument::METHOD => {
            let p: lsp_types::DidOpenTextDocumentParams =
                n.extract(note::DidOpenTextDocument::METHOD)?;
            ws.open(p.text_document.uri, p.text_document.text);
            Ok(true)
        }
        note::DidChangeTextDocument::METHOD => {
            let p: lsp_types::DidChangeTextDocumentParams =
                n.extract(note::DidChangeTextDocument::METHOD)?;
            let uri = p.text_document.uri;
            // Taken, not copied: the text of a large file is megabytes; and
            // its line table, moved through the edits.
            let (mut text, mut lines) = match ws.doc(&uri) {
                Some(k) => (
                    std::mem::take(&mut ws.docs[k].text),
                    ws.docs[k].lines.take(),
                ),
                None => Default::default(),
            };
            for c in p.content_changes {
                match c.range {
                    None => (text, lines) = (c.text, None),
                    // Incremental sync: the editor sends the edit, not the text.
                    Some(r) => {
                        let ix = lines.get_or_insert_with(|| convert::LineIndex::new(&text));
                        let lo = ix.offset(&text, r.start);
                        let hi = ix.offset(&text, r.end).max(lo);
                        text.replace_range(lo..hi, &c.text);
                        ix.edit(&text, lo, hi, c.text.len());
                    }
                }
            }
            ws.change(&uri, text, lines);
            Ok(true)
        }
        note::DidCloseTextDocument::METHOD => {
            let p: lsp_types::DidCloseTextDocumentParams =
                n.extract(note::DidCloseTextDocument::METHOD)?;
            if let Some(uri) = ws.close(&p.text_document.uri) {
                publish(conn, uri, Vec::new())?;
            }
            Ok(true)
        }
        note::DidChangeConfiguration::METHOD => {
            let p: lsp_types::DidChangeConfigurationParams =
                n.extract(note::DidChangeConfiguration::METHOD)?;
            let was = ws.settings.cr_type_hints;
            if let Err(e) = ws.settings.update(&p.settings) {
                eprintln!("ilc lsp: settings: {e}");
            }
            if ws.settings.hint_refresh && was != ws.settings.cr_type_hints {
                // The client's answer is ignored (see `serve`).
                conn.sender.send(Message::Request(Request::new(
                    lsp_server::RequestId::from("ilc/inlayHintRefresh".to_string()),
                    req::InlayHintRefreshRequest::METHOD.to_string(),
                    Value::Null,
                )))?;
            }
            Ok(false)
        }
        _ => Ok(false),
    }
}

/// What a request handler gives: the answer, or an LSP error.
type Answer<T> = Result<T, (ErrorCode, String)>;

/// `r`'s parameters as those of request `R`, handed to `f`, and its answer
/// as JSON: every typed request goes through here.
fn answer<R: req::Request>(
    r: Request,
    f: impl FnOnce(R::Params) -> Answer<R::Result>,
) -> Answer<Value> {
    let (_, p) = r
        .extract::<R::Params>(R::METHOD)
        .map_err(|e| (ErrorCode::InvalidParams, format!("{e:?}")))?;
    serde_json::to_value(f(p)?).map_err(|e| (ErrorCode::InternalError, e.to_string()))
}

/// Answer a request (unknown methods get `MethodNotFound`).
fn request(ws: &Workspace, r: Request) -> Response {
    let id = r.id.clone();
    let method = r.method.clone();
    let result: Answer<Value> = match method.as_str() {
        req::HoverRequest::METHOD => answer::<req::HoverRequest>(r, |p| {
            let tp = p.text_document_position_params;
            Ok(hover::hover(ws, &tp.text_document.uri, tp.position))
        }),
        req::GotoDefinition::METHOD => answer::<req::GotoDefinition>(r, |p| {
            let tp = p.text_document_position_params;
            Ok(navigation::definition(ws, &tp.text_document.uri, tp.position).map(Into::into))
        }),
        req::References::METHOD => answer::<req::References>(r, |p| {
            let tp = p.text_document_position;
            let decl = p.context.include_declaration;
            Ok(Some(navigation::references(
                ws,
                &tp.text_document.uri,
                tp.position,
                decl,
            )))
        }),
        req::DocumentHighlightRequest::METHOD => answer::<req::DocumentHighlightRequest>(r, |p| {
            let tp = p.text_document_position_params;
            Ok(Some(navigation::highlight(
                ws,
                &tp.text_document.uri,
                tp.position,
            )))
        }),
        req::PrepareRenameRequest::METHOD => answer::<req::PrepareRenameRequest>(r, |p| {
            Ok(navigation::prepare_rename(
                ws,
                &p.text_document.uri,
                p.position,
            ))
        }),
        req::Rename::METHOD => answer::<req::Rename>(r, |p| {
            let tp = p.text_document_position;
            navigation::rename(ws, &tp.text_document.uri, tp.position, &p.new_name)
                .map_err(|m| (ErrorCode::InvalidParams, m))
        }),
        req::DocumentSymbolRequest::METHOD => answer::<req::DocumentSymbolRequest>(r, |p| {
            Ok(Some(symbols::document(ws, &p.text_document.uri).into()))
        }),
        req::WorkspaceSymbolRequest::METHOD => answer::<req::WorkspaceSymbolRequest>(r, |p| {
            Ok(Some(lsp_types::WorkspaceSymbolResponse::Flat(
                symbols::workspace(ws, &p.query),
            )))
        }),
        req::Completion::METHOD => answer::<req::Completion>(r, |p| {
            let tp = p.text_document_position;
            Ok(Some(
                completion::complete(ws, &tp.text_document.uri, tp.position).into(),
            ))
        }),
        req::InlayHintRequest::METHOD => answer::<req::InlayHintRequest>(r, |p| {
            Ok(Some(inlay::hints(ws, &p.text_document.uri, p.range)))
        }),
        req::SignatureHelpRequest::METHOD => answer::<req::SignatureHelpRequest>(r, |p| {
            let tp = p.text_document_position_params;
            Ok(signature::help(ws, &tp.text_document.uri, tp.position))
        }),
        req::SemanticTokensFullRequest::METHOD => {
            answer::<req::SemanticTokensFullRequest>(r, |p| {
                Ok(semantic::full(ws, &p.text_document.uri).map(Into::into))
            })
        }
        req::CodeActionRequest::METHOD => answer::<req::CodeActionRequest>(r, |p| {
            Ok(Some(code_actions(ws, &p.text_document.uri, p.range)))
        }),
        req::Formatting::METHOD => {
            answer::<req::Formatting>(r, |p| Ok(formatting::edits(ws, &p.text_document.uri, None)))
        }
        req::RangeFormatting::METHOD => answer::<req::RangeFormatting>(r, |p| {
            Ok(formatting::edits(ws, &p.text_document.uri, Some(p.range)))
        }),
        // For the tests of the panic guard only: refused unless asked for.
        "ilc/testPanic" if std::env::var_os("ILC_LSP_TEST_PANIC").is_some() => {
            panic!("ilc/testPanic: a deliberate panic")
        }
        m => Err((ErrorCode::MethodNotFound, format!("`{m}` is not supported"))),
    };
    match result {
        Ok(v) => Response::new_ok(id, v),
        Err((code, msg)) => Response::new_err(id, code as i32, msg),
    }
}

/// The quick fixes of the diagnostics that touch `range` (the checker's
/// fixes: did-you-mean renames, a conversion before an instruction, `T#`
/// before a duration).
fn code_actions(
    ws: &Workspace,
    uri: &lsp_types::Uri,
    range: lsp_types::Range,
) -> lsp_types::CodeActionResponse {
    let Some(k) = ws.doc(uri) else {
        return Vec::new();
    };
    let touches = |r: &lsp_types::Range| r.start <= range.end && range.start <= r.end;
    let fixes = ws.analysis.fixes.get(k).map_or(&[][..], Vec::as_slice);
    let rewrite =
        refactor::formal_form(ws, uri, range).map(lsp_types::CodeActionOrCommand::CodeAction);
    let diags = ws
        .analysis
        .diagnostics
        .get(k)
        .map_or(&[][..], Vec::as_slice);
    fixes
        .iter()
        .filter(|f| touches(&f.range))
        .map(|f| {
            // lsp_types' own map type: `Uri` is a key by its text.
            #[allow(clippy::mutable_key_type)]
            let changes = std::iter::once((uri.clone(), f.edits.clone())).collect();
            lsp_types::CodeActionOrCommand::CodeAction(lsp_types::CodeAction {
                title: f.title.clone(),
                kind: Some(lsp_types::CodeActionKind::QUICKFIX),
                diagnostics: Some(
                    diags
                        .iter()
                        .filter(|d| d.range == f.range)
                        .cloned()
                        .collect(),
                ),
                edit: Some(lsp_types::WorkspaceEdit {
                    changes: Some(changes),
                    ..Default::default()
                }),
                is_preferred: Some(true),
                ..Default::default()
            })
        })
        .chain(rewrite)
        .collect()
}
