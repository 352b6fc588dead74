! Fortran bindings of abut's C contact interface (abut/abut_contact.h; examples/host/README.md):
! the same functions through iso_c_binding. Handles are type(c_ptr); node indices are 0-based as
! in C; strings passed in end with c_null_char (abut_name below adds it). abut_error_message returns the
! message of the last call that failed.
module abut_contact
  use, intrinsic :: iso_c_binding
  implicit none
  private
  public :: abut_contact_stats, ABUT_OK, ABUT_ERROR, abut_name, abut_error_message
  public :: abut_contact_settings_create, abut_contact_settings_set, abut_contact_settings_destroy
  public :: abut_surface_create, abut_surface_add_facets, abut_surface_add_shells
  public :: abut_surface_destroy, abut_contact_create, abut_contact_destroy, abut_contact_apply
  public :: abut_contact_stable_step, abut_contact_get_stats

  integer(c_int), parameter :: ABUT_OK = 0, ABUT_ERROR = 1

  type, bind(c) :: abut_contact_stats
    real(c_double) :: force(3)
    real(c_double) :: normal_force, tangential_force, elastic_energy, damping_energy
    real(c_double) :: friction_energy, released_energy, max_penetration, active_points
  end type

  interface
    function abut_last_error() bind(c) result(text)
      import :: c_ptr
      type(c_ptr) :: text
    end function
    function abut_contact_settings_create() bind(c) result(settings)
      import :: c_ptr
      type(c_ptr) :: settings
    end function
    function abut_contact_settings_set(settings, name, value) bind(c) result(status)
      import :: c_ptr, c_char, c_double, c_int
      type(c_ptr), value :: settings
      character(kind=c_char), dimension(*), intent(in) :: name
      real(c_double), value :: value
      integer(c_int) :: status
    end function
    subroutine abut_contact_settings_destroy(settings) bind(c)
      import :: c_ptr
      type(c_ptr), value :: settings
    end subroutine
    function abut_surface_create() bind(c) result(surface)
      import :: c_ptr
      type(c_ptr) :: surface
    end function
    function abut_surface_add_facets(surface, count, nodes, part, penalty, thickness) &
        bind(c) result(status)
      import :: c_ptr, c_size_t, c_int32_t, c_int64_t, c_double, c_int
      type(c_ptr), value :: surface
      integer(c_size_t), value :: count
      integer(c_int32_t), intent(in) :: nodes(*)
      integer(c_int64_t), value :: part
      real(c_double), value :: penalty, thickness
      integer(c_int) :: status
    end function
    function abut_surface_add_shells(surface, count, nodes, part, penalty, thickness) &
        bind(c) result(status)
      import :: c_ptr, c_size_t, c_int32_t, c_int64_t, c_double, c_int
      type(c_ptr), value :: surface
      integer(c_size_t), value :: count
      integer(c_int32_t), intent(in) :: nodes(*)
      integer(c_int64_t), value :: part
      real(c_double), value :: penalty, thickness
      integer(c_int) :: status
    end function
    subroutine abut_surface_destroy(surface) bind(c)
      import :: c_ptr
      type(c_ptr), value :: surface
    end subroutine
    function abut_contact_create(settings, surface1, surface2, node_count, node_mass, x, y, z, &
                                 secondary_count, secondary_nodes) bind(c) result(contact)
      import :: c_ptr, c_size_t, c_double
      type(c_ptr), value :: settings, surface1, surface2
      integer(c_size_t), value :: node_count, secondary_count
      real(c_double), intent(in) :: node_mass(*), x(*), y(*), z(*)
      type(c_ptr), value :: secondary_nodes
      type(c_ptr) :: contact
    end function
    subroutine abut_contact_destroy(contact) bind(c)
      import :: c_ptr
      type(c_ptr), value :: contact
    end subroutine
    function abut_contact_apply(contact, time, dt, x, y, z, vx, vy, vz, fx, fy, fz) &
        bind(c) result(status)
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: contact
      real(c_double), value :: time, dt
      real(c_double), intent(in) :: x(*), y(*), z(*), vx(*), vy(*), vz(*)
      real(c_double), intent(inout) :: fx(*), fy(*), fz(*)
      integer(c_int) :: status
    end function
    function abut_contact_stable_step(contact) bind(c) result(step)
      import :: c_ptr, c_double
      type(c_ptr), value :: contact
      real(c_double) :: step
    end function
    function abut_contact_get_stats(contact, stats) bind(c) result(status)
      import :: c_ptr, c_int, abut_contact_stats
      type(c_ptr), value :: contact
      type(abut_contact_stats), intent(out) :: stats
      integer(c_int) :: status
    end function
    function c_strlen(text) bind(c, name="strlen") result(length)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: text
      integer(c_size_t) :: length
    end function
  end interface

contains

  ! A setting's name as C wants it (ended by c_null_char).
  function abut_name(name) result(c_name)
    character(len=*), intent(in) :: name
    character(kind=c_char, len=len_trim(name) + 1) :: c_name
    c_name = trim(name) // c_null_char
  end function

  ! The message of the last call that failed.
  function abut_error_message() result(message)
    character(len=:), allocatable :: message
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    n = int(c_strlen(abut_last_error()))
    call c_f_pointer(abut_last_error(), chars, [n])
    allocate(character(len=n) :: message)
    do i = 1, n
      message(i:i) = chars(i)
    end do
  end function

end module abut_contact
