// A build for AVX2 and FMA (CMake's RT_AVX2, cmake/RtCpu.cmake) stops on a CPU without them with a
// message that says what to do, instead of dying of an illegal instruction somewhere in its
// start-up. The check runs as the first of the program's own constructors (priority 101, before
// every static object's), and is itself compiled for the plain x86-64 instruction set. Every
// program linking rt_core links this file: rt_core asks the linker for rt_cpu_guard.
#include <unistd.h>

#ifdef RT_BUILT_FOR_AVX2

extern "C" __attribute__((constructor(101), target("no-avx"), used)) void rt_cpu_guard() {
    __builtin_cpu_init();  // a constructor may run before libgcc's own has filled in the CPU's
    if (__builtin_cpu_supports("avx2") == 0 || __builtin_cpu_supports("fma") == 0) {
        static constexpr char kMessage[] =
            "error: this program was built for CPUs with AVX2 and FMA (CMake option RT_AVX2, on "
            "by default when the building machine has them), and this CPU lacks them: configure "
            "with -DRT_AVX2=OFF and build again\n";
        [[maybe_unused]] const ssize_t written =
            write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
        _exit(1);
    }
}

#else

extern "C" __attribute__((used)) void rt_cpu_guard() {}

#endif
