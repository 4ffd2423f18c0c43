//! The checker's diagnostics as LSP diagnostics: the code, the message
//! `ilc check` prints with its label, notes and help, and the secondary
//! places as related information.

use il_codegen::diag::{Diagnostic, Severity};
use lsp_types::{DiagnosticRelatedInformation, DiagnosticSeverity, Location, NumberOrString, Uri};

use super::convert::LineIndex;

/// The diagnostics of the document at `uri`, whose `text` `ix` indexes.
pub fn convert(
    uri: &Uri,
    text: &str,
    ix: &LineIndex,
    diags: &[Diagnostic],
) -> Vec<lsp_types::Diagnostic> {
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
                    location: Location::new(uri.clone(), ix.range(text, *span)),
                    message: label.clone(),
                })
                .collect();
            lsp_types::Diagnostic {
                range: ix.range(text, d.span),
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
