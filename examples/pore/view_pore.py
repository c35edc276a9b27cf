"""Show the fluid and the particles of examples/pore together in ParaView.

Run from the directory the example wrote its output into:
    pvpython view_pore.py [--dt 0.01]               # renders pore_view.png (last time step)
    pvpython view_pore.py [--dt 0.01] --animation   # also pore_view.####.png per frame
(--dt: the DEM time step of the run, 1/n_dem in the example; default 0.01.)
or load it in the ParaView GUI: View > Python Shell > Run Script.

Fluid: fluid_vtk/fluid.pvd (written by fix lbm/pore ... vtk N fluid_vtk): a slice through
the pore axis coloured by the velocity magnitude, and the solid (node_type 1) as a
translucent contour. Particles: particles_vtk/particles_*.vtp (LIGGGHTS dump custom/vtk, XML .vtp)
as spheres of their own radius, in one colour. Both series carry the same
simulation time (the script writes particles_vtk/particles.pvd with time = step * dt, the
fluid series already carries time = fluid steps * dt_lbm), so the animation keeps them in step.

Without ParaView: examples/paper/render_snapshot.py draws a slice of the fluid speed with the
particles coloured by drag per mass (|f_pore[1-3]| / mass) from the same files, with VTK's
Python bindings and matplotlib; `render_snapshot.py . --at peak` takes the frame nearest the
run's highest pressure peak (tools/run_example.sh writes it as snapshot_peak.png).
"""
import glob
import sys

from paraview.simple import (Calculator, Contour, GetActiveViewOrCreate, GetAnimationScene,
                             Glyph, PVDReader, Render, SaveAnimation,
                             SaveScreenshot, Show, Slice, ColorBy)

fluid = PVDReader(registrationName="fluid", FileName="fluid_vtk/fluid.pvd")
particle_files = sorted(glob.glob("particles_vtk/particles_*.vtp"),
                        key=lambda name: int(name.rsplit("_", 1)[1].split(".")[0]))
if not particle_files:
    sys.exit("no particles_vtk/particles_*.vtp: run the example first (it writes them)")
dt = float(sys.argv[sys.argv.index("--dt") + 1]) if "--dt" in sys.argv else 0.01
# A .pvd series gives each particle file its simulation time (the dump names carry the step).
with open("particles_vtk/particles.pvd", "w") as pvd:
    pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
    for name in particle_files:
        step = int(name.rsplit("_", 1)[1].split(".")[0])
        pvd.write(f'  <DataSet timestep="{step * dt:.9g}" file="{name.split("/", 1)[1]}"/>\n')
    pvd.write("</Collection>\n</VTKFile>\n")
particles = PVDReader(registrationName="particles", FileName="particles_vtk/particles.pvd")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1400, 700]
view.Background = [1.0, 1.0, 1.0]

# Fluid: slice through the pore axis (the scene is centred on y = z = W/2).
bounds = fluid.GetDataInformation().GetBounds()
centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, (bounds[4] + bounds[5]) / 2]
cut = Slice(registrationName="axial_slice", Input=fluid)
cut.SliceType.Origin = centre
cut.SliceType.Normal = [0.0, 0.0, 1.0]
speed = Calculator(registrationName="fluid_speed", Input=cut, ResultArrayName="speed",
                   Function="mag(velocity)")
speed_display = Show(speed, view)
ColorBy(speed_display, ("POINTS", "speed"))
speed_display.RescaleTransferFunctionToDataRange(True, False)
speed_display.SetScalarBarVisibility(view, True)

walls = Contour(registrationName="walls", Input=fluid, ContourBy=["POINTS", "node_type"],
                Isosurfaces=[0.5])
walls_display = Show(walls, view)
walls_display.Opacity = 0.25
walls_display.DiffuseColor = [0.6, 0.6, 0.6]

# Particles: true-size spheres (radius column of the dump).
spheres = Glyph(registrationName="particles_as_spheres", Input=particles, GlyphType="Sphere")
spheres.ScaleArray = ["POINTS", "radius"]
spheres.ScaleFactor = 2.0  # the sphere glyph has diameter 1: scale by 2 R
spheres.GlyphMode = "All Points"
spheres.GlyphType.ThetaResolution = 16
spheres.GlyphType.PhiResolution = 16
sphere_display = Show(spheres, view)
sphere_display.DiffuseColor = [0.8, 0.3, 0.1]

view.CameraPosition = [centre[0], centre[1] - 3.0 * (bounds[1] - bounds[0]), centre[2] + 20.0]
view.CameraFocalPoint = centre
view.CameraViewUp = [0.0, 0.0, 1.0]

scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = scene.EndTime
Render(view)
SaveScreenshot("pore_view.png", view)
print("wrote pore_view.png")
if "--animation" in sys.argv:
    SaveAnimation("pore_view.png", view, FrameWindow=[0, len(scene.TimeKeeper.TimestepValues) - 1])
    print("wrote pore_view.####.png")
