! A Fortran host of abut's contact library (abut_contact.f90 over abut/abut_contact.h): a square
! plate of 4 nodes (1 kg each) falls 10 mm under gravity onto a fixed square and comes to rest
! under mass-proportional damping; at rest the contact carries its weight, 4 m g. Units: m, kg, s.
! Central differences, with the damping at the mean of the half steps' velocities.
program falling_plate
  use, intrinsic :: iso_c_binding
  use abut_contact
  implicit none
  integer, parameter :: n = 8  ! nodes 0-3: the fixed square (normal up); 4-7: the plate
  real(c_double), parameter :: g = 9.81d0, c = 20.0d0, penalty = 1.0d8, thickness = 0.1d0
  real(c_double) :: x(n), y(n), z(n), vx(n), vy(n), vz(n), fx(n), fy(n), fz(n), mass(n)
  real(c_double) :: t, dt, h
  integer(c_int32_t) :: lower(4) = [0, 1, 2, 3], upper(4) = [4, 7, 6, 5]
  type(c_ptr) :: settings, s1, s2, contact
  type(abut_contact_stats) :: stats
  integer :: i

  x = [0d0, 1d0, 1d0, 0d0, 0.2d0, 0.8d0, 0.8d0, 0.2d0] * 0.1d0
  y = [0d0, 0d0, 1d0, 1d0, 0.2d0, 0.2d0, 0.8d0, 0.8d0] * 0.1d0
  z = [0d0, 0d0, 0d0, 0d0, 0.01d0, 0.01d0, 0.01d0, 0.01d0]
  mass = [1d6, 1d6, 1d6, 1d6, 1d0, 1d0, 1d0, 1d0]
  vx = 0; vy = 0; vz = 0

  settings = abut_contact_settings_create()
  call check(abut_contact_settings_set(settings, abut_name("node_to_surface"), 1d0))
  call check(abut_contact_settings_set(settings, abut_name("one_way"), 1d0))
  s1 = abut_surface_create()
  s2 = abut_surface_create()
  call check(abut_surface_add_facets(s1, 1_c_size_t, upper, 1_c_int64_t, penalty, thickness))
  call check(abut_surface_add_facets(s2, 1_c_size_t, lower, 2_c_int64_t, penalty, thickness))
  contact = abut_contact_create(settings, s1, s2, int(n, c_size_t), mass, x, y, z, 0_c_size_t, &
                                c_null_ptr)
  if (.not. c_associated(contact)) call check(ABUT_ERROR)

  t = 0; dt = 1d-4
  do while (t < 2d0)
    fx = 0; fy = 0; fz = 0
    fz(5:8) = -mass(5:8) * g
    call check(abut_contact_apply(contact, t, dt, x, y, z, vx, vy, vz, fx, fy, fz))
    h = 0.5d0 * c * dt
    do i = 5, 8
      vz(i) = ((1 - h) * vz(i) + fz(i) / mass(i) * dt) / (1 + h)
      z(i) = z(i) + vz(i) * dt
    end do
    t = t + dt
    dt = min(1d-4, 0.9d0 * abut_contact_stable_step(contact))
  end do
  call check(abut_contact_get_stats(contact, stats))
  print '(a, f12.9)', 'at rest: N / (4 m g) = ', stats%normal_force / (4 * g)

  call abut_contact_destroy(contact)
  call abut_surface_destroy(s1)
  call abut_surface_destroy(s2)
  call abut_contact_settings_destroy(settings)

contains

  subroutine check(status)
    integer(c_int), intent(in) :: status
    if (status /= ABUT_OK) then
      print '(2a)', 'abut: ', abut_error_message()
      stop 1
    end if
  end subroutine

end program falling_plate
