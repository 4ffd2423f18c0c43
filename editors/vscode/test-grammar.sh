#!/usr/bin/env bash
# The TextMate grammar's syntax tests (test/*.il, the `(* ^^^ scope` lines):
# runs vscode-tmgrammar-test, fetched from the npm registry at a pinned
# version into a temporary folder (nothing is installed here).
set -euo pipefail
cd "$(dirname "$0")"
if ! command -v npm >/dev/null; then
    echo "test-grammar.sh: npm is needed (apt-get install npm, or Node.js from nodejs.org)" >&2
    exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
npm install --silent --no-audit --no-fund --prefix "$tmp" vscode-tmgrammar-test@0.1.3 >/dev/null
"$tmp/node_modules/.bin/vscode-tmgrammar-test" -g syntaxes/il.tmLanguage.json 'test/*.il'
