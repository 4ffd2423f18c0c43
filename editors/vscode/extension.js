// The VS Code client of `ilc lsp`: starts the server over stdio for IL
// files (and PLCopen XML projects) and passes the `ilc.*` settings on.
"use strict";

const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration("ilc");
  const command = config.get("path", "ilc");
  const server = { command, args: ["lsp"], transport: TransportKind.stdio };
  const documentSelector = [{ scheme: "file", language: "iec-il" }];
  if (config.get("plcopen", true)) {
    documentSelector.push({ scheme: "file", pattern: "**/*.xml" });
  }
  client = new LanguageClient(
    "ilc",
    "IEC 61131-3 IL (ilc)",
    { run: server, debug: server },
    {
      documentSelector,
      // Read by the server at start (`inlayHints.crType`, `encoding`: how
      // the workspace files that are not UTF-8 are read) and sent again
      // whenever the `ilc` settings change.
      initializationOptions: {
        inlayHints: { crType: config.get("inlayHints.crType", true) },
        ...(config.get("encoding") ? { encoding: config.get("encoding") } : {}),
      },
      synchronize: { configurationSection: "ilc" },
    },
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
