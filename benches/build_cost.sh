#!/usr/bin/env bash
# Group 3, build cost for users: cold and incremental `cargo build` of small
# crates around the README motor, each in its own empty target directory:
#   plain          the motor written by hand (il-std only)
#   baseline       a trivial proc macro with syn 2 (default features) + quote,
#                  the cost of any crate that uses a derive
#   with_macro     il!(file = "plc/motor.il"), il-macros' default features
#   with_macro_plcopen  the same with il-macros' `plcopen` feature (XML
#                  import: roxmltree, memchr and the translation)
#   with_buildrs   build.rs + include!
# and the last two again with `[profile.dev.build-override] opt-level = 2`
# (`*_opt2`), the README's advice for large IL files.
# The project's crates are path dependencies here, and cargo compiles path
# dependencies incrementally in dev builds, which it never does for a
# dependency from crates.io (incremental compilation adds 25-35% to
# il-codegen's cold compile). So that the crates cost what they cost a user
# who takes them from crates.io, each crate gets `incremental = false` for
# the project's crates and the baseline's macro crate (a derive crate comes
# from crates.io too); the user's own crate stays incremental.
# BUILD_COST_PATH_INCREMENTAL=1 leaves cargo's path-dependency default.
# Prints one line per crate. Takes several minutes (cold builds compile syn
# and the compiler). Usage: bash benches/build_cost.sh [WORKDIR]
# BUILD_COST_CRATES="baseline with_macro" builds only those crates;
# BUILD_COST_ROUNDS=3 repeats the list that many times, so that crates
# compared with each other alternate under the same load.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-$(mktemp -d)}
mkdir -p "$work"
il="$repo/examples/motor.il"

mk() { # name deps build-deps profile
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
$4
$registry
EOT
  cp "$repo/Cargo.lock" "$d/Cargo.lock"
}
opt2=$'[profile.dev.build-override]\nopt-level = 2'
# As a crates.io dependency: not incremental (see the top of this file).
registry=""
if [ -z "${BUILD_COST_PATH_INCREMENTAL:-}" ]; then
  for p in il-std il-codegen il-macros trivial_macro; do
    registry+=$'\n'"[profile.dev.package.$p]"$'\nincremental = false'
  done
fi

mk plain "" "" ""
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

# The baseline: a derive-style proc macro crate with syn + quote.
pm="$work/trivial_macro"; rm -rf "$pm"; mkdir -p "$pm/src"
cat > "$pm/Cargo.toml" <<EOT
[package]
name = "trivial_macro"
version = "0.0.0"
edition = "2024"
publish = false
[lib]
proc-macro = true
[dependencies]
syn = "2"
quote = "1"
EOT
cat > "$pm/src/lib.rs" <<'EOT'
use proc_macro::TokenStream;
#[proc_macro_derive(Named)]
pub fn named(input: TokenStream) -> TokenStream {
    let ast: syn::DeriveInput = syn::parse(input).unwrap();
    let name = &ast.ident;
    let text = name.to_string();
    quote::quote!(impl #name { pub const NAME: &'static str = #text; }).into()
}
EOT
mk baseline "trivial_macro = { path = \"$pm\" }" "" ""
cat > "$work/baseline/src/lib.rs" <<'EOT'
#[derive(trivial_macro::Named, Default)]
pub struct Motor { pub run: bool }
EOT

mk with_macro_plcopen "il-macros = { path = \"$repo/il-macros\", features = [\"plcopen\"] }" "" ""
echo 'il_macros::il!(file = "plc/motor.il");' > "$work/with_macro_plcopen/src/lib.rs"

for v in "" _opt2; do
  prof=""; [ -n "$v" ] && prof="$opt2"
  mk "with_macro$v" "il-macros = { path = \"$repo/il-macros\" }" "" "$prof"
  echo 'il_macros::il!(file = "plc/motor.il");' > "$work/with_macro$v/src/lib.rs"
  mk "with_buildrs$v" "" "il-codegen = { path = \"$repo/il-codegen\" }" "$prof"
  echo 'include!(concat!(env!("OUT_DIR"), "/motor.rs"));' > "$work/with_buildrs$v/src/lib.rs"
  cat > "$work/with_buildrs$v/build.rs" <<'EOT'
fn main() -> Result<(), il_codegen::Error> {
    il_codegen::Builder::new().file("plc/motor.il").compile()?;
    Ok(())
}
EOT
done

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
t() { local s=$(date +%s.%N); "$@" >/dev/null 2>&1; echo "$(date +%s.%N) - $s" | bc; }
crates=${BUILD_COST_CRATES:-plain baseline with_macro with_macro_plcopen with_buildrs with_macro_opt2 with_buildrs_opt2}
for round in $(seq "${BUILD_COST_ROUNDS:-1}"); do
for c in $crates; do
  cd "$work/$c"
  rm -rf target
  cold=$(t cargo build --offline)
  touch src/lib.rs
  inc_rs=$(t cargo build --offline)
  echo "    (* edited *)" >> plc/motor.il; touch plc/motor.il
  inc_il=$(t cargo build --offline)
  printf '%-18s cold %6.2f s   touch lib.rs %5.2f s   edit motor.il %5.2f s   (load %s)\n' \
    "$c" "$cold" "$inc_rs" "$inc_il" "$(cut -d' ' -f1 /proc/loadavg)"
done
done
