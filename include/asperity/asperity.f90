! The asperity C API (asperity/asperity.h) for Fortran 2003 and later: `use asperity`.
!
! Interfaces (iso_c_binding), the C structs as interoperable types, the status codes as
! parameters. The module holds no code, so its compiled asperity.mod (installed beside the
! headers) is all a program needs besides the library:
!
!   gfortran prog.f90 $(pkg-config --cflags --libs asperity)
!
! (another compiler: compile this file first). Strings passed in (paths, distribution and side
! names) end with c_null_char; an error buffer is a character(kind=c_char, len=N) variable
! passed with its length, and holds a NUL-terminated message on failure:
!
!   character(kind=c_char, len=512) :: err
!   table = asperity_table_open(c_null_ptr, err, int(len(err), c_size_t))   ! the default table
!   curve = asperity_curve_open(table, "weibull"//c_null_char, "bounded"//c_null_char, &
!                               1.73_c_double, err, int(len(err), c_size_t))
!   if (.not. c_associated(curve)) print *, err(1:index(err, c_null_char) - 1)
!   load = asperity_eval(curve, 3_c_int, -0.4_c_double)                    ! X_3/2(-0.4)
!
! A path other than the default: pass c_loc of a NUL-terminated character variable with the
! target attribute, e.g. path = "file.h5"//c_null_char; table = asperity_table_open(c_loc(path), ...).
! twice_order: 0 -> X_0, 1 -> X_1/2, 2 -> X_1, 3 -> X_3/2, 4 -> X_2, 5 -> X_5/2.
! Separations follow docs/model.md (origin convention); physical quantities are in SI units.
module asperity
  use, intrinsic :: iso_c_binding, only: c_ptr, c_null_ptr, c_char, c_null_char, c_int, c_double, &
                                         c_size_t, c_associated, c_loc, c_f_pointer
  implicit none
  private
  public :: c_ptr, c_null_ptr, c_char, c_null_char, c_int, c_double, c_size_t, c_associated, c_loc, c_f_pointer

  ! Status codes (enum asperity_status): returned by asperity_table_load, asperity_curve_load,
  ! asperity_eval_batch, asperity_contact, asperity_model_at_*; asperity_status_string says each in words.
  integer(c_int), parameter, public :: ASPERITY_OK = 0
  integer(c_int), parameter, public :: ASPERITY_BAD_HANDLE = 1      ! NULL curve, model, table or output
  integer(c_int), parameter, public :: ASPERITY_BAD_ORDER = 2       ! twice_order outside 0..5, or a bad order mask
  integer(c_int), parameter, public :: ASPERITY_BAD_SEPARATION = 3  ! NaN or infinite: those outputs NaN
  integer(c_int), parameter, public :: ASPERITY_BAD_PARAMETER = 4   ! a physical parameter <= 0 or not finite
  ! asperity_table_load: why a table file was refused
  integer(c_int), parameter, public :: ASPERITY_FILE_MISSING = 5     ! no such file
  integer(c_int), parameter, public :: ASPERITY_FILE_UNREADABLE = 6  ! not a regular file, no permission, read error
  integer(c_int), parameter, public :: ASPERITY_NOT_HDF5 = 7         ! neither an asperity table nor any HDF5 file
  integer(c_int), parameter, public :: ASPERITY_OTHER_SCHEMA = 8     ! an HDF5 file, but not an asperity table
  integer(c_int), parameter, public :: ASPERITY_OTHER_VERSION = 9    ! another format version: regenerate it
  integer(c_int), parameter, public :: ASPERITY_DAMAGED = 10         ! truncated, extended or changed since written
  integer(c_int), parameter, public :: ASPERITY_INVALID_TABLE = 11   ! intact, but breaks the schema or its limits
  ! asperity_curve_load, asperity_model_open
  integer(c_int), parameter, public :: ASPERITY_BAD_NAME = 12        ! dist or side is not a known name
  integer(c_int), parameter, public :: ASPERITY_NOT_IN_TABLE = 13    ! no such curve set, or the shape is outside it
  integer(c_int), parameter, public :: ASPERITY_NO_MEMORY = 14
  integer(c_int), parameter, public :: ASPERITY_FAILURE = 15         ! anything else: the message says what
  ! asperity_eval_batch, asperity_contact, asperity_model_at_*: a separation outside the curve's
  ! range (a scene table's: asperity_curve_range); those outputs NaN
  integer(c_int), parameter, public :: ASPERITY_OUTSIDE_RANGE = 16

  ! Order masks for asperity_curve_load: bit 2**twice_order keeps X_(twice_order/2); combine with
  ! ior(). A curve of fewer orders takes less memory and answers NaN for the others.
  integer(c_int), parameter, public :: ASPERITY_ORDER_I0 = 1_c_int    ! count
  integer(c_int), parameter, public :: ASPERITY_ORDER_I1_2 = 2_c_int  ! stiffness
  integer(c_int), parameter, public :: ASPERITY_ORDER_I1 = 4_c_int    ! area
  integer(c_int), parameter, public :: ASPERITY_ORDER_I3_2 = 8_c_int  ! load
  integer(c_int), parameter, public :: ASPERITY_ORDER_I2 = 16_c_int
  integer(c_int), parameter, public :: ASPERITY_ORDER_I5_2 = 32_c_int
  integer(c_int), parameter, public :: ASPERITY_ALL_ORDERS = 63_c_int
  integer(c_int), parameter, public :: ASPERITY_CONTACT_ORDERS = 15_c_int  ! what asperity_contact needs

  ! asperity_contact: N summits of radius R, height scale sigma_s, modulus E* (docs/model.md section 3)
  type, bind(c), public :: asperity_contact_state
    real(c_double) :: count, area, load, stiffness, stiffness_ratio
  end type

  ! asperity_model_at_separation_batch: which quantity (asperity_quantity)
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_COUNT = 0_c_int          ! summits in contact
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_REAL_AREA = 1_c_int      ! m^2
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_AREA_FRACTION = 2_c_int  ! A / A0
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_LOAD = 3_c_int           ! N
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_PRESSURE = 4_c_int       ! Pa
  integer(c_int), parameter, public :: ASPERITY_QUANTITY_STIFFNESS = 5_c_int      ! N/m

  ! asperity_model_at_*: a physical surface against a flat, SI units
  type, bind(c), public :: asperity_physical_state
    real(c_double) :: separation           ! m, from the model's datum (asperity_model_open: the origin)
    real(c_double) :: mean_separation      ! m, from the mean summit height
    real(c_double) :: count                ! summits in contact
    real(c_double) :: real_area            ! m^2
    real(c_double) :: area_fraction        ! A / A0
    real(c_double) :: load                 ! N
    real(c_double) :: pressure             ! Pa, load / A0
    real(c_double) :: stiffness            ! N/m
    real(c_double) :: stiffness_over_load  ! 1/m
  end type

  ! asperity_contact_curves_*: a contact-curves table (a measured surface's exact contact), SI units
  type, bind(c), public :: asperity_contact_curves_state
    real(c_double) :: separation     ! m, from the table's datum (a map's mean plane)
    real(c_double) :: pressure       ! Pa, mean nominal pressure
    real(c_double) :: stiffness      ! Pa/m, -dp/d(separation)
    real(c_double) :: area_fraction  ! real area / nominal area
  end type
  type, bind(c), public :: asperity_contact_curves_info
    real(c_double) :: min_separation, max_separation, min_pressure, max_pressure
    real(c_double) :: max_rel_error(3), measured_rel_error(3)  ! pressure, stiffness, area fraction
    real(c_double) :: safety_factor, solver_tolerance, contact_modulus, nominal_area, mean_summit_height
    integer(c_int) :: nodes, check_points
  end type

  public :: asperity_table_load, asperity_table_open, asperity_table_close
  public :: asperity_curve_load, asperity_curve_open, asperity_curve_order_mask, asperity_curve_close
  public :: asperity_curve_range
  public :: asperity_eval, asperity_eval_log, asperity_eval_batch, asperity_eval_log_batch
  public :: asperity_contact, asperity_standardized_from_origin, asperity_origin_from_standardized
  public :: asperity_version, asperity_status_string, asperity_contact_modulus, asperity_height_scale_from_rms
  public :: asperity_model_open, asperity_model_close, asperity_model_at_separation, asperity_model_at_load
  public :: asperity_model_at_pressure, asperity_model_at_real_area
  public :: asperity_contact_modulus_given
  public :: asperity_model_pressure_overclosure_card, asperity_tabulated_pressure_overclosure_card
  public :: asperity_model_pressure_overclosure_card_options, asperity_contact_curves_pressure_overclosure_card_options
  public :: asperity_model_open_datum, asperity_model_datum, asperity_model_warnings
  public :: asperity_model_at_separation_batch
  public :: asperity_contact_curves_load, asperity_contact_curves_close, asperity_contact_curves_get_info
  public :: asperity_contact_curves_pressure, asperity_contact_curves_stiffness, asperity_contact_curves_area_fraction
  public :: asperity_contact_curves_separation, asperity_contact_curves_at_separation
  public :: asperity_contact_curves_at_pressure, asperity_contact_curves_pressure_overclosure_card
  public :: asperity_contact_curves_summit_count, asperity_contact_curves_has_tension
  public :: asperity_contact_curves_summit_count_max_rel_error
  public :: asperity_contact_curves_pull_off_pressure, asperity_contact_curves_pull_off_separation
  public :: asperity_contact_curves_approach_separation

  interface
    ! Loads a table: path c_null_ptr for the default table ($ASPERITY_TABLE if set). Returns
    ! ASPERITY_OK and sets table, or a status saying why (ASPERITY_FILE_MISSING ..
    ! ASPERITY_INVALID_TABLE), table = c_null_ptr and a message in err.
    function asperity_table_load(path, table, err, err_size) bind(c, name="asperity_table_load")
      import :: c_ptr, c_char, c_size_t, c_int
      type(c_ptr), value :: path
      type(c_ptr), intent(out) :: table
      character(kind=c_char), dimension(*) :: err
      integer(c_size_t), value :: err_size
      integer(c_int) :: asperity_table_load
    end function

    ! The same, returning the table, or c_null_ptr on failure (the reason only as text in err).
    function asperity_table_open(path, err, err_size) bind(c, name="asperity_table_open")
      import :: c_ptr, c_char, c_size_t
      type(c_ptr), value :: path
      character(kind=c_char), dimension(*) :: err
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_table_open
    end function

    subroutine asperity_table_close(table) bind(c, name="asperity_table_close")
      import :: c_ptr
      type(c_ptr), value :: table
    end subroutine

    ! dist: "weibull" or "gaussian"; side: "tail" or "bounded"; shape ignored for the Gaussian.
    ! order_mask: ASPERITY_ALL_ORDERS or an ior() of ASPERITY_ORDER_* bits. Returns ASPERITY_OK and
    ! sets curve, or a status (ASPERITY_BAD_NAME, ASPERITY_NOT_IN_TABLE, ASPERITY_BAD_ORDER, ...),
    ! curve = c_null_ptr and a message in err.
    function asperity_curve_load(table, dist, side, shape, order_mask, curve, err, err_size) &
        bind(c, name="asperity_curve_load")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      character(kind=c_char), dimension(*) :: dist, side, err
      real(c_double), value :: shape
      integer(c_int), value :: order_mask
      type(c_ptr), intent(out) :: curve
      integer(c_size_t), value :: err_size
      integer(c_int) :: asperity_curve_load
    end function

    ! The orders a curve holds (ASPERITY_ORDER_* bits: test with iand); 0 for c_null_ptr.
    pure function asperity_curve_order_mask(curve) bind(c, name="asperity_curve_order_mask")
      import :: c_ptr, c_int
      type(c_ptr), value, intent(in) :: curve
      integer(c_int) :: asperity_curve_order_mask
    end function

    ! asperity_curve_load with all orders, returning the curve or c_null_ptr (the reason in err).
    function asperity_curve_open(table, dist, side, shape, err, err_size) bind(c, name="asperity_curve_open")
      import :: c_ptr, c_char, c_double, c_size_t
      type(c_ptr), value :: table
      character(kind=c_char), dimension(*) :: dist, side, err
      real(c_double), value :: shape
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_curve_open
    end function

    subroutine asperity_curve_close(curve) bind(c, name="asperity_curve_close")
      import :: c_ptr
      type(c_ptr), value :: curve
    end subroutine

    ! The separations the curve serves, [min, max]: IEEE -infinity and +infinity for a full
    ! table's curves, a scene table's range for its curves; outside it every query answers NaN
    ! (the bounded side at sep >= 0 excepted: exactly 0). Returns ASPERITY_OK, or
    ! ASPERITY_BAD_HANDLE for c_null_ptr (min and max NaN).
    function asperity_curve_range(curve, min, max) bind(c, name="asperity_curve_range")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: curve
      real(c_double), intent(out) :: min, max
      integer(c_int) :: asperity_curve_range
    end function

    ! X_n(sep); NaN on bad input. Pure: no side effect, so usable in pure procedures.
    pure function asperity_eval(curve, twice_order, sep) bind(c, name="asperity_eval")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value, intent(in) :: curve
      integer(c_int), value, intent(in) :: twice_order
      real(c_double), value, intent(in) :: sep
      real(c_double) :: asperity_eval
    end function

    ! ln X_n(sep): finite wherever X_n > 0, -inf where it is exactly 0.
    pure function asperity_eval_log(curve, twice_order, sep) bind(c, name="asperity_eval_log")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value, intent(in) :: curve
      integer(c_int), value, intent(in) :: twice_order
      real(c_double), value, intent(in) :: sep
      real(c_double) :: asperity_eval_log
    end function

    ! out(i) = asperity_eval(curve, twice_order, sep(i)), i = 1..n, vectorized. Returns a status.
    function asperity_eval_batch(curve, twice_order, sep, out, n) bind(c, name="asperity_eval_batch")
      import :: c_ptr, c_int, c_double, c_size_t
      type(c_ptr), value :: curve
      integer(c_int), value :: twice_order
      real(c_double), dimension(*), intent(in) :: sep
      real(c_double), dimension(*), intent(out) :: out
      integer(c_size_t), value :: n
      integer(c_int) :: asperity_eval_batch
    end function

    function asperity_eval_log_batch(curve, twice_order, sep, out, n) bind(c, name="asperity_eval_log_batch")
      import :: c_ptr, c_int, c_double, c_size_t
      type(c_ptr), value :: curve
      integer(c_int), value :: twice_order
      real(c_double), dimension(*), intent(in) :: sep
      real(c_double), dimension(*), intent(out) :: out
      integer(c_size_t), value :: n
      integer(c_int) :: asperity_eval_log_batch
    end function

    function asperity_contact(curve, summit_count, summit_radius, height_scale, contact_modulus, sep, out) &
        bind(c, name="asperity_contact")
      import :: c_ptr, c_int, c_double, asperity_contact_state
      type(c_ptr), value :: curve
      real(c_double), value :: summit_count, summit_radius, height_scale, contact_modulus, sep
      type(asperity_contact_state), intent(out) :: out
      integer(c_int) :: asperity_contact
    end function

    ! standardized = (sep - mean)/rms, from the mean summit height
    pure function asperity_standardized_from_origin(curve, sep) bind(c, name="asperity_standardized_from_origin")
      import :: c_ptr, c_double
      type(c_ptr), value, intent(in) :: curve
      real(c_double), value, intent(in) :: sep
      real(c_double) :: asperity_standardized_from_origin
    end function

    pure function asperity_origin_from_standardized(curve, standardized) bind(c, name="asperity_origin_from_standardized")
      import :: c_ptr, c_double
      type(c_ptr), value, intent(in) :: curve
      real(c_double), value, intent(in) :: standardized
      real(c_double) :: asperity_origin_from_standardized
    end function

    ! A NUL-terminated C string in static storage (read it with c_f_pointer; examples/fortran_example.f90).
    function asperity_version() bind(c, name="asperity_version")
      import :: c_ptr
      type(c_ptr) :: asperity_version
    end function

    function asperity_status_string(status) bind(c, name="asperity_status_string")
      import :: c_ptr, c_int
      integer(c_int), value :: status
      type(c_ptr) :: asperity_status_string
    end function

    ! 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; NaN for E <= 0 or nu outside (-1, 0.5].
    pure function asperity_contact_modulus(young1, poisson1, young2, poisson2) bind(c, name="asperity_contact_modulus")
      import :: c_double
      real(c_double), value, intent(in) :: young1, poisson1, young2, poisson2
      real(c_double) :: asperity_contact_modulus
    end function

    ! The height scale asperity_model_open takes from the rms summit height GW users measure [m]:
    ! for dist "weibull" the scale sigma_s = rms / c_a, c_a = sqrt(Gamma(1 + 2/a) - Gamma(1 + 1/a)**2)
    ! (a = 1.6: rms = 0.574 sigma_s); for "gaussian" the rms itself (shape ignored). NaN for an
    ! unknown dist, or an rms or Weibull shape that is not a positive finite number.
    pure function asperity_height_scale_from_rms(dist, shape, rms) bind(c, name="asperity_height_scale_from_rms")
      import :: c_char, c_double
      character(kind=c_char), dimension(*), intent(in) :: dist
      real(c_double), value, intent(in) :: shape, rms
      real(c_double) :: asperity_height_scale_from_rms
    end function

    ! A physical surface (SI units): dist "weibull" (shape 0.3..50, side "tail" or "bounded") or
    ! "gaussian" (side "tail"). c_null_ptr and a message in err for a bad parameter.
    function asperity_model_open(table, dist, side, shape, height_scale, summit_radius, summit_density, &
                                 nominal_area, contact_modulus, err, err_size) bind(c, name="asperity_model_open")
      import :: c_ptr, c_char, c_double, c_size_t
      type(c_ptr), value :: table
      character(kind=c_char), dimension(*) :: dist, side, err
      real(c_double), value :: shape, height_scale, summit_radius, summit_density, nominal_area, contact_modulus
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_model_open
    end function

    ! E* from what a user gave: the contact modulus itself or the four E1, nu1, E2, nu2 together
    ! (ieee_value(x, ieee_quiet_nan): not given). out is NaN where none is given;
    ! ASPERITY_BAD_PARAMETER and a message in err for both, the four incomplete, or a bad value.
    function asperity_contact_modulus_given(contact_modulus, young1, poisson1, young2, poisson2, out, err, err_size) &
        bind(c, name="asperity_contact_modulus_given")
      import :: c_char, c_double, c_int, c_size_t
      real(c_double), value :: contact_modulus, young1, poisson1, young2, poisson2
      real(c_double), intent(out) :: out
      character(kind=c_char), dimension(*) :: err
      integer(c_size_t), value :: err_size
      integer(c_int) :: asperity_contact_modulus_given
    end function

    ! FE export: the model's pressure-overclosure card (format "calculix", "abaqus" or "csv"; units
    ! "si" or "mm"; description c_null_ptr or c_loc of a NUL-terminated text) into buffer if it fits
    ! in buffer_size bytes; length receives its length (buffer_size 0 with c_null_ptr asks for it).
    function asperity_model_pressure_overclosure_card(model, pressure_min, pressure_max, tolerance, format, units, &
                                                      description, buffer, buffer_size, length, err, err_size) &
        bind(c, name="asperity_model_pressure_overclosure_card")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      type(c_ptr), value :: model, description, buffer
      real(c_double), value :: pressure_min, pressure_max, tolerance
      character(kind=c_char), dimension(*) :: format, units, err
      integer(c_size_t), value :: buffer_size, err_size
      integer(c_size_t), intent(out) :: length
      integer(c_int) :: asperity_model_pressure_overclosure_card
    end function

    ! The card with the command line's options and defaults: datum c_null_ptr (zero-pressure, the
    ! default) or c_loc of a NUL-terminated name; max_points 0 for the default cap (200 for calculix);
    ! face_size in the card's units (NaN: not given).
    function asperity_model_pressure_overclosure_card_options(model, pressure_min, pressure_max, tolerance, format, &
                                                              units, datum, max_points, face_size, description, &
                                                              buffer, buffer_size, length, err, err_size) &
        bind(c, name="asperity_model_pressure_overclosure_card_options")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      type(c_ptr), value :: model, datum, description, buffer
      real(c_double), value :: pressure_min, pressure_max, tolerance, face_size
      character(kind=c_char), dimension(*) :: format, units, err
      integer(c_size_t), value :: max_points, buffer_size, err_size
      integer(c_size_t), intent(out) :: length
      integer(c_int) :: asperity_model_pressure_overclosure_card_options
    end function

    ! The same for contact curves.
    function asperity_contact_curves_pressure_overclosure_card_options(curves, pressure_min, pressure_max, tolerance, &
                                                                       format, units, datum, max_points, face_size, &
                                                                       description, buffer, buffer_size, length, err, &
                                                                       err_size) &
        bind(c, name="asperity_contact_curves_pressure_overclosure_card_options")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      type(c_ptr), value :: curves, datum, description, buffer
      real(c_double), value :: pressure_min, pressure_max, tolerance, face_size
      character(kind=c_char), dimension(*) :: format, units, err
      integer(c_size_t), value :: max_points, buffer_size, err_size
      integer(c_size_t), intent(out) :: length
      integer(c_int) :: asperity_contact_curves_pressure_overclosure_card_options
    end function

    ! The same card for a curve given by count points (ascending in overclosure [m], pressures [Pa]).
    function asperity_tabulated_pressure_overclosure_card(pressures, overclosures, count, format, units, description, &
                                                          notes, buffer, buffer_size, length, err, err_size) &
        bind(c, name="asperity_tabulated_pressure_overclosure_card")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      real(c_double), dimension(*), intent(in) :: pressures, overclosures
      integer(c_size_t), value :: count, buffer_size, err_size
      character(kind=c_char), dimension(*) :: format, units, err
      type(c_ptr), value :: description, notes, buffer
      integer(c_size_t), intent(out) :: length
      integer(c_int) :: asperity_tabulated_pressure_overclosure_card
    end function

    ! asperity_model_open with the separation datum (NUL-terminated): "origin" (asperity_model_open's),
    ! "mean-summit" or "mean-plane" (then mean_summit_height [m], the mean summit height above the
    ! mean plane; NaN for the others).
    function asperity_model_open_datum(table, dist, side, shape, height_scale, summit_radius, summit_density, &
                                       nominal_area, contact_modulus, datum, mean_summit_height, err, err_size) &
        bind(c, name="asperity_model_open_datum")
      import :: c_ptr, c_char, c_double, c_size_t
      type(c_ptr), value :: table
      character(kind=c_char), dimension(*) :: dist, side, datum, err
      real(c_double), value :: shape, height_scale, summit_radius, summit_density, nominal_area, contact_modulus
      real(c_double), value :: mean_summit_height
      integer(c_size_t), value :: err_size
      type(c_ptr) :: asperity_model_open_datum
    end function

    ! The model's datum's name (a C string in static storage; c_null_ptr for c_null_ptr).
    function asperity_model_datum(model) bind(c, name="asperity_model_datum")
      import :: c_ptr
      type(c_ptr), value :: model
      type(c_ptr) :: asperity_model_datum
    end function

    ! Units caught: how many implausible values the surface has; their lines into buffer.
    function asperity_model_warnings(model, buffer, buffer_size) bind(c, name="asperity_model_warnings")
      import :: c_ptr, c_char, c_size_t
      type(c_ptr), value :: model
      character(kind=c_char), dimension(*) :: buffer
      integer(c_size_t), value :: buffer_size
      integer(c_size_t) :: asperity_model_warnings
    end function

    ! out(i) = the quantity (ASPERITY_QUANTITY_*) at separation(i), i = 1..n: the batch lookup.
    function asperity_model_at_separation_batch(model, quantity, separation, out, n) &
        bind(c, name="asperity_model_at_separation_batch")
      import :: c_ptr, c_int, c_double, c_size_t
      type(c_ptr), value :: model
      integer(c_int), value :: quantity
      real(c_double), dimension(*), intent(in) :: separation
      real(c_double), dimension(*), intent(out) :: out
      integer(c_size_t), value :: n
      integer(c_int) :: asperity_model_at_separation_batch
    end function

    ! Contact curves against separation (asperity.h): path a C string (c_null_char-terminated).
    function asperity_contact_curves_load(path, curves, err, err_size) bind(c, name="asperity_contact_curves_load")
      import :: c_ptr, c_char, c_size_t, c_int
      character(kind=c_char), dimension(*) :: path, err
      type(c_ptr), intent(out) :: curves
      integer(c_size_t), value :: err_size
      integer(c_int) :: asperity_contact_curves_load
    end function

    subroutine asperity_contact_curves_close(curves) bind(c, name="asperity_contact_curves_close")
      import :: c_ptr
      type(c_ptr), value :: curves
    end subroutine

    function asperity_contact_curves_get_info(curves, out) bind(c, name="asperity_contact_curves_get_info")
      import :: c_ptr, c_int, asperity_contact_curves_info
      type(c_ptr), value :: curves
      type(asperity_contact_curves_info), intent(out) :: out
      integer(c_int) :: asperity_contact_curves_get_info
    end function

    function asperity_contact_curves_pressure(curves, separation) bind(c, name="asperity_contact_curves_pressure")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double), value :: separation
      real(c_double) :: asperity_contact_curves_pressure
    end function

    function asperity_contact_curves_stiffness(curves, separation) bind(c, name="asperity_contact_curves_stiffness")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double), value :: separation
      real(c_double) :: asperity_contact_curves_stiffness
    end function

    function asperity_contact_curves_area_fraction(curves, separation) &
        bind(c, name="asperity_contact_curves_area_fraction")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double), value :: separation
      real(c_double) :: asperity_contact_curves_area_fraction
    end function

    function asperity_contact_curves_separation(curves, pressure) bind(c, name="asperity_contact_curves_separation")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double), value :: pressure
      real(c_double) :: asperity_contact_curves_separation
    end function

    ! summits in contact per m^2 (NaN for a table without the count)
    function asperity_contact_curves_summit_count(curves, separation) bind(c, name="asperity_contact_curves_summit_count")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double), value :: separation
      real(c_double) :: asperity_contact_curves_summit_count
    end function

    ! the summit count's stored relative bound (NaN for a table without the count)
    function asperity_contact_curves_summit_count_max_rel_error(curves) &
        bind(c, name="asperity_contact_curves_summit_count_max_rel_error")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double) :: asperity_contact_curves_summit_count_max_rel_error
    end function

    ! adhesive curves: 1 with a tensile part (signed pressure), else 0
    function asperity_contact_curves_has_tension(curves) bind(c, name="asperity_contact_curves_has_tension")
      import :: c_ptr, c_int
      type(c_ptr), value :: curves
      integer(c_int) :: asperity_contact_curves_has_tension
    end function

    ! the greatest tension (Pa, < 0) and where (m); NaN without tension or outside the range
    function asperity_contact_curves_pull_off_pressure(curves) bind(c, name="asperity_contact_curves_pull_off_pressure")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double) :: asperity_contact_curves_pull_off_pressure
    end function

    function asperity_contact_curves_pull_off_separation(curves) &
        bind(c, name="asperity_contact_curves_pull_off_separation")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double) :: asperity_contact_curves_pull_off_separation
    end function

    ! the withdrawal branch's approach separation (m): finite for an adhesive law's withdrawal
    ! (unloading) curves, NaN for the approach branch, curves without tension or a null handle
    function asperity_contact_curves_approach_separation(curves) &
        bind(c, name="asperity_contact_curves_approach_separation")
      import :: c_ptr, c_double
      type(c_ptr), value :: curves
      real(c_double) :: asperity_contact_curves_approach_separation
    end function

    function asperity_contact_curves_at_separation(curves, separation, out) &
        bind(c, name="asperity_contact_curves_at_separation")
      import :: c_ptr, c_int, c_double, asperity_contact_curves_state
      type(c_ptr), value :: curves
      real(c_double), value :: separation
      type(asperity_contact_curves_state), intent(out) :: out
      integer(c_int) :: asperity_contact_curves_at_separation
    end function

    function asperity_contact_curves_at_pressure(curves, pressure, out) bind(c, name="asperity_contact_curves_at_pressure")
      import :: c_ptr, c_int, c_double, asperity_contact_curves_state
      type(c_ptr), value :: curves
      real(c_double), value :: pressure
      type(asperity_contact_curves_state), intent(out) :: out
      integer(c_int) :: asperity_contact_curves_at_pressure
    end function

    function asperity_contact_curves_pressure_overclosure_card(curves, pressure_min, pressure_max, tolerance, format, &
                                                               units, description, buffer, buffer_size, length, err, &
                                                               err_size) &
        bind(c, name="asperity_contact_curves_pressure_overclosure_card")
      import :: c_ptr, c_char, c_double, c_int, c_size_t
      type(c_ptr), value :: curves, description, buffer
      real(c_double), value :: pressure_min, pressure_max, tolerance
      character(kind=c_char), dimension(*) :: format, units, err
      integer(c_size_t), value :: buffer_size, err_size
      integer(c_size_t), intent(out) :: length
      integer(c_int) :: asperity_contact_curves_pressure_overclosure_card
    end function

    subroutine asperity_model_close(model) bind(c, name="asperity_model_close")
      import :: c_ptr
      type(c_ptr), value :: model
    end subroutine

    function asperity_model_at_separation(model, separation, out) bind(c, name="asperity_model_at_separation")
      import :: c_ptr, c_int, c_double, asperity_physical_state
      type(c_ptr), value :: model
      real(c_double), value :: separation
      type(asperity_physical_state), intent(out) :: out
      integer(c_int) :: asperity_model_at_separation
    end function

    function asperity_model_at_load(model, load, out) bind(c, name="asperity_model_at_load")
      import :: c_ptr, c_int, c_double, asperity_physical_state
      type(c_ptr), value :: model
      real(c_double), value :: load
      type(asperity_physical_state), intent(out) :: out
      integer(c_int) :: asperity_model_at_load
    end function

    function asperity_model_at_pressure(model, pressure, out) bind(c, name="asperity_model_at_pressure")
      import :: c_ptr, c_int, c_double, asperity_physical_state
      type(c_ptr), value :: model
      real(c_double), value :: pressure
      type(asperity_physical_state), intent(out) :: out
      integer(c_int) :: asperity_model_at_pressure
    end function

    function asperity_model_at_real_area(model, real_area, out) bind(c, name="asperity_model_at_real_area")
      import :: c_ptr, c_int, c_double, asperity_physical_state
      type(c_ptr), value :: model
      real(c_double), value :: real_area
      type(asperity_physical_state), intent(out) :: out
      integer(c_int) :: asperity_model_at_real_area
    end function
  end interface

end module asperity
