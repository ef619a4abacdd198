! asperity from Fortran (`use asperity`, include/asperity/asperity.f90): the Gaussian tail,
! Greenwood-Tripp F_5/2 for a mixed-lubrication code, a stiffness/load ratio, a batch of
! separations, a curve of two orders only, a physical surface given by its rms summit height,
! and the error paths with their status codes. Build against an installed tree with gfortran alone:
!   gfortran fortran_example.f90 $(pkg-config --cflags --libs asperity)
program fortran_example
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
  use asperity
  implicit none

  character(kind=c_char, len=512) :: err
  character(kind=c_char, len=64), target :: path
  type(c_ptr) :: table, gaussian, missing, worn, model
  type(asperity_physical_state) :: state
  real(c_double) :: h, f52, ratio, sigma, lo, hi
  real(c_double) :: separations(5), values(5)
  integer(c_int) :: status
  integer :: i

  write (*, '(2a)') 'asperity ', c_text(asperity_version())

  status = asperity_table_load(c_null_ptr, table, err, int(len(err), c_size_t))  ! the default table
  if (status /= ASPERITY_OK) then
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

  ! A worn surface (Weibull a = 1.6, bounded side) holding only stiffness and load: less memory,
  ! NaN for the orders it does not hold.
  status = asperity_curve_load(table, "weibull"//c_null_char, "bounded"//c_null_char, 1.6_c_double, &
                               ior(ASPERITY_ORDER_I1_2, ASPERITY_ORDER_I3_2), worn, err, int(len(err), c_size_t))
  if (status /= ASPERITY_OK) stop 'cannot load the worn curve'
  if (asperity_curve_order_mask(worn) /= ior(ASPERITY_ORDER_I1_2, ASPERITY_ORDER_I3_2)) stop 'wrong order mask'
  if (.not. ieee_is_nan(asperity_eval(worn, 0_c_int, -0.5_c_double))) stop 'an order not held answered'
  ! The separations it serves: every one for the default table's curves (a scene table's curve
  ! serves its scene's range, and answers NaN outside it).
  status = asperity_curve_range(worn, lo, hi)
  if (status /= ASPERITY_OK .or. ieee_is_finite(lo) .or. ieee_is_finite(hi)) stop 'a full table limits its range'
  write (*, '(a, es16.7)') 'worn surface, K_3/2(-0.5) =', asperity_eval(worn, 3_c_int, -0.5_c_double)
  call asperity_curve_close(worn)

  ! A physical surface given by its rms summit height (0.5 um), as GW users measure it: the
  ! Weibull scale sigma_s is rms / 0.574 for a = 1.6.
  sigma = asperity_height_scale_from_rms("weibull"//c_null_char, 1.6_c_double, 0.5e-6_c_double)
  write (*, '(a, es12.5, a)') 'rms summit height 0.5 um: Weibull scale sigma_s =', sigma, ' m'
  model = asperity_model_open(table, "weibull"//c_null_char, "tail"//c_null_char, 1.6_c_double, sigma, &
                              1e-4_c_double, 1e10_c_double, 1e-4_c_double, &
                              asperity_contact_modulus(2.1e11_c_double, 0.3_c_double, 2.1e11_c_double, 0.3_c_double), &
                              err, int(len(err), c_size_t))
  if (.not. c_associated(model)) stop 'cannot open the model'
  status = asperity_model_at_load(model, 1.0_c_double, state)
  if (status /= ASPERITY_OK) stop 'the load query failed'
  write (*, '(a, es12.5, a, es12.5, a)') 'at 1 N: separation from the mean summit height', state%mean_separation, &
    ' m, stiffness', state%stiffness, ' N/m'
  call asperity_model_close(model)

  ! Errors: a status and a message.
  missing = asperity_curve_open(table, "weibull"//c_null_char, "tail"//c_null_char, 1000.0_c_double, &
                                err, int(len(err), c_size_t))
  if (c_associated(missing)) stop 'a shape outside the table was accepted'
  write (*, '(a)') 'expected error: '//err(1:index(err, c_null_char) - 1)
  path = "/nonexistent/table.h5"//c_null_char
  status = asperity_table_load(c_loc(path), missing, err, int(len(err), c_size_t))
  if (status /= ASPERITY_FILE_MISSING .or. c_associated(missing)) stop 'a missing file was not reported'
  write (*, '(a)') 'expected status: '//c_text(asperity_status_string(status))

  call asperity_curve_close(gaussian)
  call asperity_table_close(table)

contains

  ! A NUL-terminated C string in static storage (asperity_version, asperity_status_string) as text.
  function c_text(pointer) result(text)
    type(c_ptr), intent(in) :: pointer
    character(len=:), allocatable :: text
    character(kind=c_char), dimension(:), pointer :: chars
    integer :: n, k
    call c_f_pointer(pointer, chars, [4096])
    n = 0
    do while (chars(n + 1) /= c_null_char)
      n = n + 1
    end do
    allocate (character(len=n) :: text)
    do k = 1, n
      text(k:k) = chars(k)
    end do
  end function

end program fortran_example
