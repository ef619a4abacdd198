! An adhesive law's withdrawal table through the Fortran module (`use asperity`; issue 41, item 2),
! as test_c_api_withdrawal.c does from C: the JKR surface of tables/scenes/jkr.toml on its
! approach branch and on its withdrawal branch after an approach to s0 = -1
! (tables/scenes/jkr-withdrawal.toml). The branch from asperity_contact_curves_approach_separation;
! the values against the loading table and against the count's closed form computed here (every
! summit that touched at s0 stays in contact up to the kink s0 sigma_s + delta_c: eta erfc(s0/sqrt 2)/2).
!   test_fortran_withdrawal APPROACH_TABLE WITHDRAWAL_TABLE
program test_fortran_withdrawal
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use asperity
  implicit none

  real(c_double), parameter :: modulus = 1.13e11_c_double, work = 0.5_c_double, radius = 1e-4_c_double
  real(c_double), parameter :: sigma = 2e-9_c_double, density = 4e8_c_double, s0 = -1.0_c_double
  real(c_double), parameter :: pi = 3.14159265358979323846_c_double
  type(c_ptr) :: approach, withdrawal
  type(asperity_contact_curves_info) :: a, w
  real(c_double) :: delta_c, u0, kink, touched, u, error, worst
  integer :: i, failures

  failures = 0
  approach = load(1)
  withdrawal = load(2)
  if (asperity_contact_curves_get_info(approach, a) /= ASPERITY_OK) call fail('info of the approach table')
  if (asperity_contact_curves_get_info(withdrawal, w) /= ASPERITY_OK) call fail('info of the withdrawal table')
  delta_c = 0.75_c_double * (pi * pi * work * work * radius / (modulus * modulus))**(1.0_c_double / 3)
  u0 = s0 * sigma
  kink = u0 + delta_c
  touched = density * 0.5_c_double * erfc(s0 / sqrt(2.0_c_double))

  ! the branch, as each table states it
  if (.not. ieee_is_nan(asperity_contact_curves_approach_separation(approach))) &
    call fail('the approach table says it is a withdrawal')
  if (asperity_contact_curves_approach_separation(withdrawal) /= u0) call fail('the approach separation is not s0 sigma_s')
  if (.not. ieee_is_nan(asperity_contact_curves_approach_separation(c_null_ptr))) call fail('a null handle answered')
  if (asperity_contact_curves_has_tension(withdrawal) /= 1) call fail('no tension')

  ! equal at s0, more tension and area after it, a greater pull-off
  if (abs(asperity_contact_curves_pressure(withdrawal, u0) / asperity_contact_curves_pressure(approach, u0) - 1) > &
      2 * (w%max_rel_error(1) + a%max_rel_error(1))) call fail('the branches differ at s0')
  worst = 0
  do i = 1, 50
    u = u0 + (w%max_separation - u0) * i / 50.0_c_double
    if (.not. asperity_contact_curves_pressure(withdrawal, u) < asperity_contact_curves_pressure(approach, u)) &
      call fail('the withdrawal holds less tension than the approach')
    if (.not. asperity_contact_curves_area_fraction(withdrawal, u) > asperity_contact_curves_area_fraction(approach, u)) &
      call fail('the withdrawal holds less area than the approach')
    if (u < kink) then
      error = abs(asperity_contact_curves_summit_count(withdrawal, u) / touched - 1)
      worst = max(worst, error)
    end if
  end do
  if (.not. asperity_contact_curves_pull_off_pressure(withdrawal) < asperity_contact_curves_pull_off_pressure(approach)) &
    call fail('the withdrawal''s pull-off is not the greater')
  write (*, '(a, es9.2, a, es9.2, a)') 'count before the kink against eta erfc(s0/sqrt 2)/2: ', worst, &
    ' (stored bound ', asperity_contact_curves_summit_count_max_rel_error(withdrawal), ')'
  if (worst > asperity_contact_curves_summit_count_max_rel_error(withdrawal)) call fail('the count is beyond its bound')
  write (*, '(a, es24.16, a)') 'withdrawal pull-off ', asperity_contact_curves_pull_off_pressure(withdrawal), ' Pa'

  call asperity_contact_curves_close(approach)
  call asperity_contact_curves_close(withdrawal)
  if (failures > 0) then
    write (*, '(i0, a)') failures, ' checks failed'
    stop 1
  end if
  write (*, '(a)') 'withdrawal served'

contains

  function load(argument) result(curves)
    integer, intent(in) :: argument
    type(c_ptr) :: curves
    character(len=4096) :: name
    character(kind=c_char, len=512) :: err
    call get_command_argument(argument, name)
    if (asperity_contact_curves_load(trim(name)//c_null_char, curves, err, int(len(err), c_size_t)) /= ASPERITY_OK) then
      write (*, '(a)') err(1:index(err, c_null_char) - 1)
      stop 2
    end if
  end function

  subroutine fail(what)
    character(len=*), intent(in) :: what
    write (*, '(2a)') 'check failed: ', what
    failures = failures + 1
  end subroutine

end program
