! The asperity C API from Fortran (iso_c_binding): the Gaussian tail, Greenwood-Tripp F_5/2
! for a mixed-lubrication code, and a stiffness/load ratio, with the error path checked.
program fortran_example
  use, intrinsic :: iso_c_binding
  implicit none

  interface
    function asperity_table_open(path, err, err_size) bind(c, name="asperity_table_open")
      import :: c_ptr, c_char, c_size_t
      type(c_ptr), value :: path
      character(kind=c_char), dimension(*) :: err
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_table_open
    end function
    function asperity_curve_open(table, dist, side, shape, err, err_size) bind(c, name="asperity_curve_open")
      import :: c_ptr, c_char, c_double, c_size_t
      type(c_ptr), value :: table
      character(kind=c_char), dimension(*) :: dist, side, err
      real(c_double), value :: shape
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_curve_open
    end function
    function asperity_eval(curve, twice_order, sep) bind(c, name="asperity_eval")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value :: curve
      integer(c_int), value :: twice_order
      real(c_double), value :: sep
      real(c_double) :: asperity_eval
    end function
    subroutine asperity_curve_close(curve) bind(c, name="asperity_curve_close")
      import :: c_ptr
      type(c_ptr), value :: curve
    end subroutine
    subroutine asperity_table_close(table) bind(c, name="asperity_table_close")
      import :: c_ptr
      type(c_ptr), value :: table
    end subroutine
  end interface

  character(kind=c_char, len=512) :: err
  type(c_ptr) :: table, gaussian, missing
  real(c_double) :: h, f52, ratio
  integer :: i

  table = asperity_table_open(c_null_ptr, err, int(len(err), c_size_t))
  if (.not. c_associated(table)) stop 'cannot open the default table'
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

  missing = asperity_curve_open(table, "weibull"//c_null_char, "tail"//c_null_char, 1000.0_c_double, &
                                err, int(len(err), c_size_t))
  if (c_associated(missing)) stop 'a shape outside the table was accepted'
  write (*, '(a)') 'expected error: '//err(1:index(err, c_null_char) - 1)

  call asperity_curve_close(gaussian)
  call asperity_table_close(table)
end program fortran_example
