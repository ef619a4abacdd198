/* Load and stiffness of a rough surface from C: a Weibull (a = 1.73) worn surface on the
 * bounded side, swept toward first contact. Build: link with the asperity runtime (see
 * examples/CMakeLists.txt). */
#include <stdio.h>

#include "asperity/asperity.h"

int main(void) {
  char err[512];
  asperity_table *table = asperity_table_open(NULL, err, sizeof err); /* the shipped table */
  if (!table) {
    fprintf(stderr, "%s\n", err);
    return 1;
  }
  asperity_curve *curve = asperity_curve_open(table, "weibull", "bounded", 1.73, err, sizeof err);
  if (!curve) {
    fprintf(stderr, "%s\n", err);
    asperity_table_close(table);
    return 1;
  }
  /* 1e6 summits of radius 50 um, sigma_s = 1 um, E* = 100 GPa */
  printf("%10s %14s %14s %14s\n", "sep", "load [N]", "stiffness[N/m]", "K/P [1/sep]");
  for (double sep = -2.0; sep < 0; sep += 0.25) {
    asperity_contact_state state;
    int status = asperity_contact(curve, 1e6, 50e-6, 1e-6, 100e9, sep, &state);
    if (status != ASPERITY_OK) {
      fprintf(stderr, "%s\n", asperity_status_string(status));
      break;
    }
    printf("%10.2f %14.6g %14.6g %14.6g\n", sep, state.load, state.stiffness, state.stiffness_ratio);
  }
  asperity_curve_close(curve);
  asperity_table_close(table);
  return 0;
}
