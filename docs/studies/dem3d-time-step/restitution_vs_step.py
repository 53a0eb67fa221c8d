"""How the 3D reference's time step moves one contact: two BBs (6 mm, the bundled density) meeting
head on at 0.3 m/s, with the reference's contact law (ViscElMat, tc = 1 ms, en = et = 0.5, as
src/sim/dem3d/polyroll_dem3d.py builds it), stepped at shares of tc from 1/50 to 1/8. Prints the
restitution the pair comes out with and the contact's duration against the asked ones.

Run with Debian's python3 (Yade's folder is put on sys.path):
    /usr/bin/python3 docs/studies/dem3d-time-step/restitution_vs_step.py
"""
import sys

sys.path.insert(1, '/usr/lib/x86_64-linux-gnu/yade-double/py')
import yade  # noqa: E402
from yade import O, utils  # noqa: E402

TC, EN, R, DENSITY, SPEED = 0.001, 0.5, 0.003, 1766.67, 0.3

print('share of tc   dt (us)   restitution (asked %.2f)   contact (ms, asked %.2f)' % (EN, TC * 1e3))
for share in (1 / 50, 1 / 30, 1 / 15, 1 / 10, 1 / 8):
    O.reset()
    m = O.materials.append(yade.ViscElMat(tc=TC, en=EN, et=EN, frictionAngle=0.25, density=DENSITY))
    a = O.bodies.append(utils.sphere((0, 0, 0), R, material=m))
    b = O.bodies.append(utils.sphere((2 * R + 1e-6, 0, 0), R, material=m))
    O.bodies[a].state.vel = yade.Vector3(SPEED / 2, 0, 0)
    O.bodies[b].state.vel = yade.Vector3(-SPEED / 2, 0, 0)
    O.engines = [yade.ForceResetter(), yade.InsertionSortCollider([yade.Bo1_Sphere_Aabb()]),
                 yade.InteractionLoop([yade.Ig2_Sphere_Sphere_ScGeom()], [yade.Ip2_ViscElMat_ViscElMat_ViscElPhys()],
                                      [yade.Law2_ScGeom_ViscElPhys_Basic()]),
                 yade.NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = TC * share
    t_in = t_out = None
    for _ in range(int(0.01 / O.dt)):
        O.step()
        touching = O.interactions.countReal() > 0
        if touching and t_in is None:
            t_in = O.time
        if t_in is not None and not touching and t_out is None:
            t_out = O.time
    e = (O.bodies[b].state.vel[0] - O.bodies[a].state.vel[0]) / SPEED
    print('1/%-11.0f %7.1f   %.4f                     %.3f' % (1 / share, O.dt * 1e6, e, (t_out - t_in) * 1e3))
