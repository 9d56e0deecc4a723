"""The ParaView GUI (under xvfb-run): paraview --script runs Examples/paraview_state.py
through this file, which checks the pipeline as test_state_script.py does, saves the
view, and ends the GUI with the result (the GUI has no --exit for a --script).

Environment: TERRALUX_PLUGIN, TERRALUX_DEM, TERRALUX_STATE_SCRIPT, TERRALUX_OUTPUT_DIR.
"""
import os
import traceback

code = 1
try:
    from paraview import simple as pv
    with open(os.environ["TERRALUX_STATE_SCRIPT"]) as f:
        exec(compile(f.read(), os.environ["TERRALUX_STATE_SCRIPT"], "exec"), {"__name__": "__main__"})
    names = sorted(name for name, _ in pv.GetSources())
    solver = pv.FindSource("HierarchicalRadiosity1")
    display = pv.GetDisplayProperties(solver, pv.GetActiveView())
    points = solver.GetDataInformation().GetNumberOfPoints()
    path = os.path.join(os.environ["TERRALUX_OUTPUT_DIR"], "paraview_gui.png")
    pv.SaveScreenshot(path, pv.GetActiveView(), ImageResolution=[1000, 700])
    ok = ("Olinda DEM" in names and list(display.ColorArrayName) == ["POINTS", "Irradiance"]
          and points == 111 * 111 and os.path.getsize(path) > 10000)
    # The GUI takes over Python's stdout; the file descriptor is still the terminal's.
    os.write(2, ("GUI: %s, coloured by %s, %d points, %s: %s\n"
                 % (names, list(display.ColorArrayName), points, path, "OK" if ok else "FAIL")).encode())
    code = 0 if ok else 1
except Exception:
    os.write(2, traceback.format_exc().encode())
os._exit(code)
