# Runtime options for the AddressSanitizer + UndefinedBehaviorSanitizer build (tools/test
# --sanitize). Sourced, not run.
sanitize_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# Leak checking stays on; lsan.supp lists the allocations that Open MPI, hwloc and the
# Trilinos static registries keep until exit on purpose. fast_unwind_on_malloc=0: Open MPI's
# libraries have no frame pointers, so the fast unwinder stops one frame below malloc
# ("<unknown module>", a component dlclosed at MPI_Finalize) and no suppression can match
# the singleton start-up's allocations; the slow unwinder reaches libmpi/libopen-pal.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:strict_string_checks=0:fast_unwind_on_malloc=0"
export LSAN_OPTIONS="suppressions=$sanitize_dir/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$sanitize_dir/ubsan.supp"
