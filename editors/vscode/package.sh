#!/usr/bin/env bash
# Packages the extension as a .vsix that VS Code installs with "Extensions:
# Install from VSIX..." (or `code --install-extension FILE`): stages the
# extension's files and the project's licence texts in a temporary folder,
# fetches its runtime dependency (vscode-languageclient) and runs vsce, both
# pinned. Writes target/ilc-il-VERSION.vsix at the repository root (or the
# path given as $1), then checks that the package holds what VS Code loads.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
if ! command -v npm >/dev/null; then
    echo "package.sh: npm is needed (apt-get install npm, or Node.js from nodejs.org)" >&2
    exit 2
fi
version=$(node -p "require('$here/package.json').version")
out=${1:-$root/target/ilc-il-$version.vsix}
mkdir -p "$(dirname "$out")"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp -r "$here/package.json" "$here/package-lock.json" "$here/extension.js" \
    "$here/language-configuration.json" "$here/README.md" "$here/syntaxes" "$tmp/"
# vsce wants one LICENSE file: the project's two licences, one after the other.
{ cat "$root/LICENSE-MIT"; printf '\n\n'; cat "$root/LICENSE-APACHE"; } > "$tmp/LICENSE"
# Only what VS Code loads: no lock file, type declarations, maps or docs of
# the dependencies.
printf '%s\n' package-lock.json 'node_modules/**/*.d.ts' 'node_modules/**/*.map' \
    'node_modules/**/*.md' > "$tmp/.vscodeignore"
(cd "$tmp" && npm ci --silent --no-audit --no-fund --omit=dev >/dev/null)
# The project has no public repository URL yet: vsce asks for one unless told.
(cd "$tmp" && npx --yes @vscode/vsce@3.9.2 package --allow-missing-repository --out "$out" >/dev/null)
listing=$(unzip -l "$out")
for f in extension/package.json extension/extension.js extension/syntaxes/il.tmLanguage.json \
    extension/language-configuration.json extension/LICENSE.txt \
    extension/node_modules/vscode-languageclient/package.json; do
    if ! grep -q " $f\$" <<<"$listing"; then
        echo "package.sh: $out lacks $f" >&2
        exit 1
    fi
done
echo "packaged $out ($(du -h "$out" | cut -f1))"
