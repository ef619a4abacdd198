! asperity from Fortran (`use asperity`, include/asperity/asperity.f90): the Gaussian tail,
! Greenwood-Tripp F_5/2 for a mixed-lubrication code, a stiffness/load ratio, a batch of
! separations, and the error path. Build against an installed tree with gfortran alone:
!   gfortran fortran_example.f90 $(pkg-config --cflags --libs asperity)
program fortran_example
  use asperity
  implicit none

  character(kind=c_char, len=512) :: err
  character(kind=c_char), dimension(:), pointer :: version
  type(c_ptr) :: table, gaussian, missing
  real(c_double) :: h, f52, ratio
  real(c_double) :: separations(5), values(5)
  integer(c_int) :: status
  integer :: i

  call c_f_pointer(asperity_version(), version, [16])
  write (*, '(a, 16a)') 'asperity ', version(1:index_of_nul(version) - 1)

  table = asperity_table_open(c_null_ptr, err, int(len(err), c_size_t))
  if (.not. c_associated(table)) then
    write (*, '(a)') err(1:index(err, c_null_char) - 1)
    stop 1
  end if
  gaussian = asperity_curve_open(table, "gaussian"//c_null_char, "tail"//c_null_char, 0.0_c_double, &
                                 err, int(len(err), c_size_t))
  if (.not. c_associated(gaussian)) stop 'cannot open the Gaussian curve'

  write (*, '(a8, 2a16)') 'h', 'F_5/2(h)', '-F_3/2''/F_3/2'
  do i = 0, 8
    h = 0.5_c_double * i
    f52 = asperity_eval(gaussian, 5_c_int, h)
    ratio = 1.5_c_double * asperity_eval(gaussian, 1_c_int, h) / asperity_eval(gaussian, 3_c_int, h)
    write (*, '(f8.2, 2es16.7)') h, f52, ratio
  end do
  ! F_5/2(0) = 2^(5/4) Gamma(7/4) / (2 sqrt(pi)), the half-normal moment
  if (abs(asperity_eval(gaussian, 5_c_int, 0.0_c_double) - 0.616634218996844_c_double) > 1e-12_c_double) &
    stop 'F_5/2(0) is wrong'

  ! Many separations at once: the vectorized batch path, the same values as one at a time.
  separations = [(0.5_c_double * i, i = 1, 5)]
  status = asperity_eval_batch(gaussian, 3_c_int, separations, values, size(separations, kind=c_size_t))
  if (status /= ASPERITY_OK) stop 'the batch call failed'
  do i = 1, 5
    if (abs(values(i) - asperity_eval(gaussian, 3_c_int, separations(i))) > 1e-13_c_double * values(i)) &
      stop 'the batch path disagrees with the scalar one'
  end do

  missing = asperity_curve_open(table, "weibull"//c_null_char, "tail"//c_null_char, 1000.0_c_double, &
                                err, int(len(err), c_size_t))
  if (c_associated(missing)) stop 'a shape outside the table was accepted'
  write (*, '(a)') 'expected error: '//err(1:index(err, c_null_char) - 1)

  call asperity_curve_close(gaussian)
  call asperity_table_close(table)

contains

  pure integer function index_of_nul(text)
    character(kind=c_char), intent(in) :: text(:)
    do index_of_nul = 1, size(text)
      if (text(index_of_nul) == c_null_char) return
    end do
  end function

end program fortran_example
