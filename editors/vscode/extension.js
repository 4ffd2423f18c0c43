// The VS Code client of `ilc lsp`: starts the server over stdio for IL
// files (and PLCopen XML projects) and passes the `ilc.*` settings on.
// It also starts `ilc debug` for launch configurations of type `ilc`, and
// shows the debugger's flow control (the CR after each line the stopped
// scan ran, from the adapter's custom `flow` request) as inline values.
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
      // the workspace files that are not UTF-8 are read, `dialect`) and sent again
      // whenever the `ilc` settings change.
      initializationOptions: {
        inlayHints: { crType: config.get("inlayHints.crType", true) },
        ...(config.get("encoding") ? { encoding: config.get("encoding") } : {}),
        dialect: config.get("dialect", "iec"),
      },
      synchronize: { configurationSection: "ilc" },
    },
  );
  context.subscriptions.push(client);
  context.subscriptions.push(
    vscode.debug.registerDebugAdapterDescriptorFactory("ilc", {
      createDebugAdapterDescriptor: () =>
        new vscode.DebugAdapterExecutable(
          vscode.workspace.getConfiguration("ilc").get("path", "ilc"),
          ["debug"],
        ),
    }),
    vscode.languages.registerInlineValuesProvider({ language: "iec-il" }, { provideInlineValues }),
  );
  return client.start();
}

// The CR after each line of the stopped scan, at the end of the line.
async function provideInlineValues(document, viewport) {
  const session = vscode.debug.activeDebugSession;
  if (!session || session.type !== "ilc") return [];
  if (!vscode.workspace.getConfiguration("ilc").get("debug.flow", true)) return [];
  let flow;
  try {
    flow = await session.customRequest("flow");
  } catch (_) {
    return [];
  }
  const values = [];
  for (const { line, cr, source } of flow.lines || []) {
    // Each line is in the file of its POU (a program may have several).
    if (source && source.path && !samePath(source.path, document.uri.fsPath)) continue;
    const l = line - 1;
    if (l < viewport.start.line || l > viewport.end.line || l >= document.lineCount) continue;
    const end = document.lineAt(l).range.end;
    values.push(new vscode.InlineValueText(new vscode.Range(end, end), `CR = ${cr}`));
  }
  return values;
}

// The adapter sends resolved paths (`\\?\C:\...` on Windows).
function samePath(a, b) {
  const norm = (p) => {
    const s = p.replace(/^\\\\\?\\/, "");
    return process.platform === "win32" ? s.toLowerCase() : s;
  };
  return norm(a) === norm(b);
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
