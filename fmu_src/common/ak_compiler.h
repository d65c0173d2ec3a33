/* Compiler hints of the FMI layers and the models, empty where the compiler has no such
 * attribute. */
#ifndef ANGULAR_KINEMATICS_AK_COMPILER_H
#define ANGULAR_KINEMATICS_AK_COMPILER_H

/* Keeps a rarely taken path (a checked call that names a bad argument) out of the function that
 * serves the usual call at every communication point: the usual path then saves fewer registers.
 * Without the attribute the code is the same, only slower. */
#if defined(__GNUC__)
#define AK_NOINLINE __attribute__((noinline))
#else
#define AK_NOINLINE
#endif

/* The reverse, for a small check that the usual path of every communication point runs: inlined
 * into each caller even where the compiler would rather share one copy. */
#if defined(__GNUC__)
#define AK_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define AK_ALWAYS_INLINE inline
#endif

/* printf-style arguments, checked by the compiler. mingw-w64 builds use its C99 printf
 * (__USE_MINGW_ANSI_STDIO=1, set by CMakeLists.txt), not msvcrt's: %zu is fine there too. */
#if defined(__MINGW32__)
#define AK_PRINTF_FORMAT(f, a) __attribute__((format(gnu_printf, f, a)))
#elif defined(__GNUC__)
#define AK_PRINTF_FORMAT(f, a) __attribute__((format(printf, f, a)))
#else
#define AK_PRINTF_FORMAT(f, a)
#endif

#endif
