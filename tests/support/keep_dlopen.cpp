// Test support for the sanitizer build only (docs/reliability.md): an
// LD_PRELOAD library whose dlclose() keeps every shared object loaded.
// Open MPI loads its components (mca_*.so) with dlopen and unloads them in
// MPI_Finalize; LeakSanitizer, which checks at exit, then sees their
// process-lifetime allocations with "<unknown module>" frames that no
// suppression can name. With the components still mapped the frames resolve
// and .ci/lsan.supp suppresses Open MPI's allocations by library name, while
// leak detection stays on for everything else. Built without sanitizer flags
// (it is preloaded into mpirun too, which is not instrumented).
extern "C" int dlclose(void*) { return 0; }
