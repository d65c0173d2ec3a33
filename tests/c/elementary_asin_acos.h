/* asin and acos of the project's elementary set (elementary.h), for the tests: special values as
 * C99 Annex F states. */
#ifndef ANGULAR_KINEMATICS_ELEMENTARY_ASIN_ACOS_H
#define ANGULAR_KINEMATICS_ELEMENTARY_ASIN_ACOS_H

double ak_asin(double x);
double ak_acos(double x);

#endif
