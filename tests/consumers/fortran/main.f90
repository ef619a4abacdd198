! An installed asperity from Fortran with gfortran alone (`use asperity`, the installed module):
!   gfortran main.f90 $(pkg-config --cflags --libs asperity)
! Gaussian F_1(s) = phi(s) - s F_0(s), F_0 = erfc(s/sqrt 2)/2, against the library.
program fortran_consumer
  use asperity
  implicit none
  character(kind=c_char, len=512) :: err
  type(c_ptr) :: table, curve
  real(c_double), parameter :: s = 0.8_c_double, pi = acos(-1.0_c_double)
  real(c_double) :: f0, f1, value

  table = asperity_table_open(c_null_ptr, err, int(len(err), c_size_t))
  if (.not. c_associated(table)) stop 1
  curve = asperity_curve_open(table, "gaussian"//c_null_char, "tail"//c_null_char, 0.0_c_double, &
                              err, int(len(err), c_size_t))
  if (.not. c_associated(curve)) stop 1
  f0 = 0.5_c_double * erfc(s / sqrt(2.0_c_double))
  f1 = exp(-0.5_c_double * s * s) / sqrt(2 * pi) - s * f0
  value = asperity_eval(curve, 2_c_int, s)
  write (*, '(a, es24.16, a, es24.16)') 'F_1(0.8) =', value, ', closed form', f1
  if (abs(value - f1) > 1e-12_c_double * f1) stop 1
  call asperity_curve_close(curve)
  call asperity_table_close(table)
end program fortran_consumer
