//! The checker's diagnostics as LSP diagnostics: the code, the message
//! `ilc check` prints with its label, notes and help, and the secondary
//! places as related information.

use il_codegen::diag::{Diagnostic, Severity};
use lsp_types::{DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString};

use super::convert::LineIndex;
use super::workspace::Doc;

pub fn convert(
    docs: &[Doc],
    lines: &[LineIndex],
    k: usize,
    diags: &[Diagnostic],
) -> Vec<lsp_types::Diagnostic> {
    let (Some(doc), Some(ix)) = (docs.get(k), lines.get(k)) else {
        return Vec::new();
    };
    diags
        .iter()
        .map(|d| {
            let mut message = d.message.clone();
            if !d.label.is_empty() {
                message.push_str(&format!("\n{}", d.label));
            }
            for n in &d.notes {
                message.push_str(&format!("\nnote: {n}"));
            }
            if let Some(h) = &d.help {
                message.push_str(&format!("\nhelp: {h}"));
            }
            let related: Vec<DiagnosticRelatedInformation> = d
                .secondary
                .iter()
                .map(|(span, label)| DiagnosticRelatedInformation {
                    location: Location::new(doc.uri.clone(), ix.range(&doc.text, *span)),
                    message: label.clone(),
                })
                .collect();
            lsp_types::Diagnostic {
                range: ix.range(&doc.text, d.span),
                severity: Some(match d.severity {
                    Severity::Error => DiagnosticSeverity::ERROR,
                    Severity::Warning => DiagnosticSeverity::WARNING,
                }),
                code: Some(NumberOrString::String(d.code.to_string())),
                source: Some("ilc".into()),
                message,
                related_information: (!related.is_empty()).then_some(related),
                ..Default::default()
            }
        })
        .collect()
}
