/* An installed asperity from C with the C compiler alone:
 *   cc main.c $(pkg-config --cflags --libs asperity)
 * J_0(s) = exp(-s^a) against the library, on the scalar and the batch path. */
#include <math.h>
#include <stdio.h>

#include "asperity/asperity.h"

int main(void) {
  char err[512];
  asperity_table *table = asperity_table_open(NULL, err, sizeof err);
  if (!table) {
    fprintf(stderr, "%s\n", err);
    return 1;
  }
  asperity_curve *curve = asperity_curve_open(table, "weibull", "tail", 1.5, err, sizeof err);
  if (!curve) {
    fprintf(stderr, "%s\n", err);
    return 1;
  }
  double sep[3] = {0.25, 1.0, 2.0}, out[3];
  int status = asperity_eval_batch(curve, 0, sep, out, 3), failures = 0;
  for (int i = 0; i < 3; ++i) {
    const double expected = exp(-pow(sep[i], 1.5));
    printf("J_0(%.2f) = %.17g, closed form %.17g\n", sep[i], out[i], expected);
    if (status != ASPERITY_OK || !(fabs(out[i] - expected) <= 1e-12 * expected) ||
        out[i] != asperity_eval(curve, 0, sep[i]))
      ++failures;
  }
  printf("asperity %s\n", asperity_version());
  asperity_curve_close(curve);
  asperity_table_close(table);
  return failures != 0;
}
