# Sourced by scripts/sanitize.sh and scripts/fuzz_smoke.sh: runtime options of the sanitizers
# and the suppression files in this folder (each suppression names its reason or upstream bug).
sanitizers_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# llvm-symbolizer turns the reports' addresses into function, file and line.
export PATH="/usr/lib/llvm-14/bin:$PATH"
# detect_leaks: LeakSanitizer runs at exit of every instrumented process (tests, CLI, fuzzers).
# strict_string_checks, detect_stack_use_after_return: stricter checks; the cost is small at -O1.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$sanitizers_dir/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# halt_on_error=0: print every race of a run, then exit non-zero (66) if there was any.
export TSAN_OPTIONS="suppressions=$sanitizers_dir/tsan.supp:print_suppressions=0:second_deadlock_stack=1:history_size=4"
