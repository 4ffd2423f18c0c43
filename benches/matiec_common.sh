# Shared by benches/matiec_compare.sh and benches/matiec_build.sh (sourced).

# The median of the numbers on standard input, one per line.
median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

# The configuration iec2c needs to write config.c and resource1.c: one
# resource running PROGRAM $1 every 10 ms (printed after the POUs).
matiec_config() {
    printf '\nCONFIGURATION config\n  RESOURCE resource1 ON PLC\n'
    printf '    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);\n'
    printf '    PROGRAM inst0 WITH task0 : %s;\n  END_RESOURCE\nEND_CONFIGURATION\n' "$1"
}
