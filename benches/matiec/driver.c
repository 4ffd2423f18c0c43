/* Driver for MATIEC's C of one benchmark program (benches/matiec_compare.sh):
 * `run <n>` runs n scans of the configuration (advancing __CURRENT_TIME by
 * 10 ms before each, as the Rust side advances its Cycle), then prints the
 * time per scan in ns and the same checksum of the outputs as
 * `il-bench`'s `scans` binary, with the same inputs (the xorshift64*
 * sequences of il_bench::inputs). Compiled with -DPROG_<name>. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "iec_std_lib.h"
#include "POUS.h"

TIME __CURRENT_TIME;
BOOL __DEBUG = 0;
void config_init__(void);
void config_run__(unsigned long tick);

static uint64_t xs;
static uint64_t next_u64(void) {
    uint64_t x = xs;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    xs = x;
    return x * 0x2545F4914F6CDD1DULL;
}
static uint64_t below(uint64_t n) { return next_u64() % n; }
static uint64_t bools(const BOOL *v, int n) {
    uint64_t s = 0;
    for (int k = 0; k < n; k++) s += (uint64_t)(k + 1) * (v[k] != 0);
    return s;
}
static uint64_t ints(const INT *v, int n) {
    uint64_t s = 0;
    for (int k = 0; k < n; k++) s += (uint64_t)(int64_t)v[k];
    return s;
}
static uint64_t bits(REAL f) { uint32_t u; memcpy(&u, &f, 4); return u; }

#define V(field) (RESOURCE1__INST0.field.value)
#if defined(PROG_interlock)
extern INTERLOCK RESOURCE1__INST0;
static void setup(void) { xs = 5; for (int k = 0; k < 64; k++) V(X).table[k] = below(3) != 0; }
static uint64_t checksum(void) { return bools(V(M).table, 256); }
#elif defined(PROG_arith_loop)
extern ARITHLOOP RESOURCE1__INST0;
static void setup(void) {}
static uint64_t checksum(void) { return (uint64_t)((int64_t)V(ACC) + (int64_t)V(X)); }
#elif defined(PROG_array_proc)
extern ARRAYPROC RESOURCE1__INST0;
static void setup(void) { xs = 9; for (int k = 0; k < 256; k++) V(SAMPLES).table[k] = (INT)(int16_t)next_u64() >> 4; }
static uint64_t checksum(void) { return ints(V(FILTERED).table, 256) + (uint64_t)(int64_t)V(PEAK); }
#elif defined(PROG_blocks)
extern BLOCKS RESOURCE1__INST0;
static void setup(void) { xs = 3; for (int k = 0; k < 100; k++) V(GO).table[k] = below(4) != 0; }
static uint64_t checksum(void) { return ints(V(COUNT).table, 100) + 1000 * bools(V(DONE).table, 100); }
#elif defined(PROG_mixed)
extern MIXED RESOURCE1__INST0;
static void setup(void) { xs = 11; for (int k = 0; k < 32; k++) V(RAW).table[k] = (INT)(int16_t)next_u64() >> 3; }
static uint64_t checksum(void) {
    return (uint64_t)((int64_t)V(ALARMS) * 1000000 + V(HIGH)) + bits(V(SUM)) + bits(V(POS));
}
#else
#error "compile with -DPROG_<program>"
#endif

int main(int argc, char **argv) {
    unsigned long n = argc > 1 ? strtoul(argv[1], NULL, 10) : 1000;
    config_init__();
    setup();
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (unsigned long t = 0; t < n; t++) {
        __CURRENT_TIME.tv_nsec += 10000000;
        if (__CURRENT_TIME.tv_nsec >= 1000000000) {
            __CURRENT_TIME.tv_nsec -= 1000000000;
            __CURRENT_TIME.tv_sec += 1;
        }
        config_run__(t);
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    double ns = ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / (n ? n : 1);
    printf("%.1f %llu\n", ns, (unsigned long long)checksum());
    return 0;
}
