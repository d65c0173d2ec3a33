/* Compiler hints of the FMI layers, empty where the compiler has no such attribute. */
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

#endif
