#!/usr/bin/env bash
# Group 3, build cost for users: cold and incremental `cargo build` of a
# small crate that uses il! (il-macros), of one that uses build.rs
# (il-codegen as a build-dependency), and of the same crate written without
# IL. Prints one line per measurement. Takes a few minutes (cold builds
# compile syn and the compiler). Usage: bash benches/build_cost.sh [WORKDIR]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d)}
mkdir -p "$work"
il="$repo/examples/motor.il"

mk() { # name deps build-deps
  local d="$work/$1"; rm -rf "$d"; mkdir -p "$d/src" "$d/plc"
  cp "$il" "$d/plc/motor.il"
  cat > "$d/Cargo.toml" <<EOT
[package]
name = "$1"
version = "0.0.0"
edition = "2024"
publish = false
[workspace]
[dependencies]
il-std = { path = "$repo/il-std" }
$2
[build-dependencies]
$3
[profile.dev.build-override]
opt-level = 2
EOT
  cp "$repo/Cargo.lock" "$d/Cargo.lock"
}

mk plain "" ""
cat > "$work/plain/src/lib.rs" <<'EOT'
//! The motor of examples/motor.il, written by hand.
#[derive(Default)]
pub struct Motor { pub start: bool, pub stop: bool, pub run: bool, pub starts: i16, edge: il_std::R_TRIG }
impl Motor {
    pub fn call(&mut self, ctx: &mut il_std::Cycle) {
        self.run = (self.start || self.run) && !self.stop;
        self.edge.CLK = self.run;
        self.edge.call(ctx);
        if self.edge.Q { self.starts = self.starts.wrapping_add(1); }
    }
}
EOT
mk with_macro "il-macros = { path = \"$repo/il-macros\" }" ""
echo 'il_macros::il!(file = "plc/motor.il");' > "$work/with_macro/src/lib.rs"
mk with_buildrs "" "il-codegen = { path = \"$repo/il-codegen\" }"
echo 'include!(concat!(env!("OUT_DIR"), "/motor.rs"));' > "$work/with_buildrs/src/lib.rs"
cat > "$work/with_buildrs/build.rs" <<'EOT'
fn main() -> Result<(), il_codegen::Error> {
    il_codegen::Builder::new().file("plc/motor.il").compile()?;
    Ok(())
}
EOT

t() { local s=$(date +%s.%N); "$@" >/dev/null 2>&1; echo "$(date +%s.%N) - $s" | bc; }
for c in plain with_macro with_buildrs; do
  cd "$work/$c"
  cold=$(t cargo build --offline)
  touch src/lib.rs
  inc_rs=$(t cargo build --offline)
  echo "    (* edited *)" >> plc/motor.il; touch plc/motor.il
  inc_il=$(t cargo build --offline)
  printf '%-13s cold %6.2f s   touch lib.rs %5.2f s   edit motor.il %5.2f s\n' "$c" "$cold" "$inc_rs" "$inc_il"
done
