/* Exact Jacobian of the general core: see kinematics_general_jacobian.h for the formulas. */
#include "kinematics_general_jacobian.h"

#include <string.h>

#include "kinematics_general.h"

/* Rows of each output block in J. */
enum {
    ROW_OMEGA_FIXED = 0,
    ROW_OMEGA_BODY = 3,
    ROW_ALPHA_FIXED = 6,
    ROW_ALPHA_BODY = 9,
    ROW_R = 12,
    ROW_Q = 21,
    ROW_W_FIXED = 25,
    ROW_W_BODY = 34,
    ROW_W_FIXED_DOT = 43,
    ROW_W_BODY_DOT = 52
};

static void cross(const double a[3], const double b[3], double out[3]) {
    const double x = a[1] * b[2] - a[2] * b[1];
    const double y = a[2] * b[0] - a[0] * b[2];
    const double z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* acc += f x */
static void add_scaled(double acc[3], double f, const double x[3]) {
    for (int r = 0; r < 3; r++) {
        acc[r] += f * x[r];
    }
}

/* Column `col` of the vector block at `row`: J[row + r][col] += x[r]. */
static void add_column(double J[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS], int row, int col,
                       const double x[3]) {
    for (int r = 0; r < 3; r++) {
        J[row + r][col] += x[r];
    }
}

/* The axes and their cross products in chain order. */
typedef struct {
    double u[3][3], v[3][3]; /* chain axes, fixed and body components */
    double U[3][3][3];       /* U[l][m] = u_l x u_m */
    double V[3][3][3];       /* V[m][l] = v_m x v_l */
    double p[3], a[3];       /* phi_dot, phi_ddot */
    int column[3];           /* theta index of chain angle m */
    double R[3][3], q[4];    /* rotation matrix and quaternion */
} chain_terms;

/* d (u_l x u_m) / d phi_j, l < m. */
static void d_fixed_pair(const chain_terms *t, int j, int l, int m, double out[3]) {
    if (j < l) {
        cross(t->u[j], t->U[l][m], out);
    } else if (j < m) {
        cross(t->u[l], t->U[j][m], out);
    } else {
        out[0] = out[1] = out[2] = 0.0;
    }
}

/* d (v_m x v_l) / d phi_j, m < l. */
static void d_body_pair(const chain_terms *t, int j, int m, int l, double out[3]) {
    if (j > l) {
        cross(t->V[m][l], t->v[j], out);
    } else if (j > m) {
        cross(t->V[m][j], t->v[l], out);
    } else {
        out[0] = out[1] = out[2] = 0.0;
    }
}

static void angle_columns(const chain_terms *t,
                          double J[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS]) {
    for (int j = 0; j < 3; j++) {
        const int col = t->column[j];
        double dof[3] = {0, 0, 0}, dob[3] = {0, 0, 0}, daf[3] = {0, 0, 0}, dab[3] = {0, 0, 0};
        double d[3];
        for (int m = j + 1; m < 3; m++) {
            add_scaled(dof, t->p[m], t->U[j][m]);
            add_scaled(daf, t->a[m], t->U[j][m]);
        }
        for (int m = 0; m < j; m++) {
            add_scaled(dob, t->p[m], t->V[m][j]);
            add_scaled(dab, t->a[m], t->V[m][j]);
        }
        for (int l = 0; l < 3; l++) {
            for (int m = l + 1; m < 3; m++) {
                d_fixed_pair(t, j, l, m, d);
                add_scaled(daf, t->p[l] * t->p[m], d);
                d_body_pair(t, j, l, m, d);
                add_scaled(dab, t->p[l] * t->p[m], d);
            }
        }
        add_column(J, ROW_OMEGA_FIXED, col, dof);
        add_column(J, ROW_OMEGA_BODY, col, dob);
        add_column(J, ROW_ALPHA_FIXED, col, daf);
        add_column(J, ROW_ALPHA_BODY, col, dab);

        /* d R / d phi_j = [u_j]x R, column by column of R. */
        for (int c = 0; c < 3; c++) {
            const double Rc[3] = {t->R[0][c], t->R[1][c], t->R[2][c]};
            cross(t->u[j], Rc, d);
            for (int r = 0; r < 3; r++) {
                J[ROW_R + 3 * r + c][col] += d[r];
            }
        }
        /* d q / d phi_j = (1/2) (0, w) q, w = u_j: scalar -w.qv, vector q0 w + w x qv. */
        const double *w = t->u[j];
        const double *q = t->q;
        const double qv[3] = {q[1], q[2], q[3]};
        cross(w, qv, d);
        J[ROW_Q][col] += -0.5 * (w[0] * qv[0] + w[1] * qv[1] + w[2] * qv[2]);
        for (int r = 0; r < 3; r++) {
            J[ROW_Q + 1 + r][col] += 0.5 * (q[0] * w[r] + d[r]);
        }

        /* W columns: u_m moves for m > j, v_m for m < j. */
        for (int m = 0; m < 3; m++) {
            const int wc = t->column[m];
            double dwf[3] = {0, 0, 0}, dwb[3] = {0, 0, 0}, dwfd[3] = {0, 0, 0},
                   dwbd[3] = {0, 0, 0};
            if (m > j) {
                memcpy(dwf, t->U[j][m], sizeof dwf);
            }
            if (m < j) {
                memcpy(dwb, t->V[m][j], sizeof dwb);
            }
            for (int l = 0; l < m; l++) {
                d_fixed_pair(t, j, l, m, d);
                add_scaled(dwfd, t->p[l], d);
            }
            for (int l = m + 1; l < 3; l++) {
                d_body_pair(t, j, m, l, d);
                add_scaled(dwbd, t->p[l], d);
            }
            for (int r = 0; r < 3; r++) {
                J[ROW_W_FIXED + 3 * r + wc][col] += dwf[r];
                J[ROW_W_BODY + 3 * r + wc][col] += dwb[r];
                J[ROW_W_FIXED_DOT + 3 * r + wc][col] += dwfd[r];
                J[ROW_W_BODY_DOT + 3 * r + wc][col] += dwbd[r];
            }
        }
    }
}

static void rate_columns(const chain_terms *t,
                         double J[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS]) {
    for (int k = 0; k < 3; k++) {
        const int col_dot = 3 + t->column[k], col_ddot = 6 + t->column[k];
        double daf[3] = {0, 0, 0}, dab[3] = {0, 0, 0};
        for (int l = 0; l < k; l++) {
            add_scaled(daf, t->p[l], t->U[l][k]);
            add_scaled(dab, t->p[l], t->V[l][k]);
        }
        for (int m = k + 1; m < 3; m++) {
            add_scaled(daf, t->p[m], t->U[k][m]);
            add_scaled(dab, t->p[m], t->V[k][m]);
        }
        add_column(J, ROW_OMEGA_FIXED, col_dot, t->u[k]);
        add_column(J, ROW_OMEGA_BODY, col_dot, t->v[k]);
        add_column(J, ROW_ALPHA_FIXED, col_dot, daf);
        add_column(J, ROW_ALPHA_BODY, col_dot, dab);
        add_column(J, ROW_ALPHA_FIXED, col_ddot, t->u[k]);
        add_column(J, ROW_ALPHA_BODY, col_ddot, t->v[k]);
        /* W_fixed_dot column m (m > k) gains u_k x u_m; W_body_dot column m (m < k) v_m x v_k. */
        for (int m = 0; m < 3; m++) {
            const int wc = t->column[m];
            for (int r = 0; r < 3; r++) {
                if (m > k) {
                    J[ROW_W_FIXED_DOT + 3 * r + wc][col_dot] += t->U[k][m][r];
                }
                if (m < k) {
                    J[ROW_W_BODY_DOT + 3 * r + wc][col_dot] += t->V[m][k][r];
                }
            }
        }
    }
}

void ak_general_jacobian(const ak_sequence *sequence, const double theta[3],
                         const double theta_dot[3], const double theta_ddot[3],
                         double J[AK_GENERAL_N_OUTPUTS][AK_GENERAL_N_INPUTS]) {
    double W_fixed[3][3], W_body[3][3], W_fixed_dot[3][3], W_body_dot[3][3];
    chain_terms t;
    ak_general_partials(sequence, theta, theta_dot, W_fixed, W_body, W_fixed_dot, W_body_dot);
    ak_general_rotation_matrix(sequence, theta, t.R);
    ak_general_quaternion(sequence, theta, t.q);
    for (int m = 0; m < 3; m++) {
        const int k = sequence->kind == AK_SPACE_FIXED ? 2 - m : m;
        t.column[m] = k;
        t.p[m] = theta_dot[k];
        t.a[m] = theta_ddot[k];
        for (int r = 0; r < 3; r++) {
            t.u[m][r] = W_fixed[r][k];
            t.v[m][r] = W_body[r][k];
        }
    }
    for (int l = 0; l < 3; l++) {
        for (int m = 0; m < 3; m++) {
            cross(t.u[l], t.u[m], t.U[l][m]);
            cross(t.v[l], t.v[m], t.V[l][m]);
        }
    }
    memset(J, 0, sizeof(double) * AK_GENERAL_N_OUTPUTS * AK_GENERAL_N_INPUTS);
    angle_columns(&t, J);
    rate_columns(&t, J);
}
