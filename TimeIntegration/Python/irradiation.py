"""Irradiation maps from a DEM: the sun, the CIE sky and interreflection summed over a
day, a month or a year (Wh/m^2, or kWh/m^2), and hours of direct sun, as a multi-band
GeoTIFF on the DEM's own grid.

    python3 -m terralux.irradiation DEM.tif -o out.tif --start 2024-06-01 --end 2024-06-30
        [--step 30] [--linke 3.0] [--reflectance 0.2] [--weather FILE.epw] [--day-of-year N]
        [--target-error E | --fast] [--target-floor W] [--seed N] [--kwh]
    mpirun -np N python3 -m terralux.irradiation DEM.tif -o out.tif ... --mpi

The equivalent GRASS call for one day: r.sun elevation=dem aspect=aspect slope=slope
day=173 step=0.5 linke_value=3.0 albedo_value=0.2 beam_rad=... diff_rad=... refl_rad=...
glob_rad=... (aspect and slope from r.slope.aspect, whose Horn normals TerraLux takes
too).
"""
import argparse
import datetime
import os
import re
import sys
import time

BANDS = ("GlobalIrradiation", "BeamIrradiation", "SkyIrradiation", "ReflectedIrradiation",
         "SunshineDuration", "SkyViewFactor", "IrradiationError")
ENERGY_BANDS = BANDS[:4] + ("IrradiationError",)
PROGRAM = "terralux.irradiation"
# The knob's coarse end (docs/validation.md measures it: at most 2 % RMS).
FAST_TARGET_ERROR = 0.04


class InputError(Exception):
    """Bad input: reported in one line, exit status 1."""


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="python3 -m " + PROGRAM,
        description="Irradiation (Wh/m^2) and sunshine duration over a DEM for a time range: "
                    "sun with exact shadows, CIE clear sky, interreflection.",
        epilog="Dates without a time are whole days in --utc-offset (default: the DEM's mean "
               "solar time to the hour); --end's day is included. Bands: " + ", ".join(BANDS) + ".")
    parser.add_argument("dem", help="a DEM GDAL reads, georeferenced")
    parser.add_argument("-o", "--output", required=True, help="the GeoTIFF to write")
    parser.add_argument("--start", help="first day (YYYY-MM-DD) or instant (ISO 8601)")
    parser.add_argument("--end", help="last day (included) or instant; default: the start's day")
    parser.add_argument("--day-of-year", type=int, metavar="N", help="one day, 1..366, of --year (as r.sun's day=)")
    parser.add_argument("--year", type=int, default=2024, help="the year of --day-of-year (default 2024)")
    parser.add_argument("--utc-offset", help="time zone of dates without one, e.g. +02:00")
    parser.add_argument("--step", type=float, default=30.0, help="time step in minutes (default 30)")
    parser.add_argument("--linke", default="3.0",
                        help="Linke turbidity: one value, or twelve comma-separated monthly values")
    parser.add_argument("--reflectance", type=float, default=0.2, help="ground reflectance (albedo), default 0.2")
    parser.add_argument("--model", choices=("esra", "ineichen-perez"), default="esra",
                        help="clear-sky model (default esra, as r.sun)")
    parser.add_argument("--sky-type", type=int, default=12, help="CIE standard general sky, 1..15 (default 12)")
    parser.add_argument("--weather", metavar="FILE",
                        help="EnergyPlus EPW or TMY3 CSV: its hourly direct and diffuse irradiance and the "
                             "Perez sky instead of the clear sky (default range: the whole --year)")
    parser.add_argument("--tolerance", type=float, default=1e-2,
                        help="the hierarchy's refinement tolerance (default 1e-2; the posts' accuracy is "
                             "--target-error's)")
    knob = parser.add_mutually_exclusive_group()
    knob.add_argument("--target-error", type=float, default=0.008, metavar="E",
                      help="the speed-accuracy knob: each post's estimated error (IrradiationError) aims at E "
                           "times what it receives (default 0.008, about 0.4 %% RMS); larger is faster")
    knob.add_argument("--fast", dest="target_error", action="store_const", const=FAST_TARGET_ERROR,
                      help="the knob's coarse end: --target-error " + str(FAST_TARGET_ERROR) + " (about 2 %% RMS)")
    parser.add_argument("--target-floor", type=float, default=None, metavar="W",
                        help="W/m^2: the error a post aims at where E of what it receives is less (default "
                             "250 E: 2 at the default E, 10 with --fast)")
    parser.add_argument("--seed", type=int, default=0, metavar="N",
                        help="another draw of the gather rays (default 0): the spread of a few seeds' maps shows "
                             "the sampling noise, which IrradiationError bounds per post")
    parser.add_argument("--kwh", action="store_true", help="write kWh/m^2 instead of Wh/m^2")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--mpi", action="store_true",
                        help="run under mpirun: each rank evaluates its piece of the DEM, rank 0 writes")
    parser.add_argument("--pieces", action="store_true",
                        help="each rank writes its own GeoTIFF (OUTPUT's name without .vrt, then _RANK.tif) and "
                             "rank 0 a GDAL VRT over them at OUTPUT (give it a .vrt name): for grids too large "
                             "for one file")
    parser.add_argument("--detail-distance", type=float, default=0.0, metavar="M",
                        help="gather hits farther than M metres take their leaf's light, not their posts' skies; "
                             "with --mpi each rank then holds those only within M of its piece (default 0: none)")
    parser.add_argument("--far-stride", type=int, default=1, metavar="N",
                        help="with --detail-distance, rays beyond it see every Nth post of the DEM, as horizon "
                             "tools see far terrain (default 1: the full resolution everywhere); each process "
                             "then reads its piece of the DEM and a halo of three detail distances only")
    return parser.parse_args(argv)


def start_mpi():
    """MPI through VTK's parallel pipeline: the global controller, once MPI runs."""
    try:
        from mpi4py import MPI  # noqa: F401 (MPI starts before VTK's controller)
        from vtkmodules.vtkParallelCore import vtkMultiProcessController
        from vtkmodules.vtkParallelMPI import vtkMPIController
    except ImportError as error:
        raise InputError("--mpi needs mpi4py (python3-mpi4py) and VTK's MPI modules: %s" % error)
    controller = vtkMPIController()
    controller.Initialize()
    vtkMultiProcessController.SetGlobalController(controller)
    return controller


def owned_posts(data):
    """Which posts of this piece (grid order) it owns: pieces share their boundary row or
    column of posts, which belongs to the piece below it, so that sums over the ranks
    count each post once."""
    import numpy
    e = data.GetExtent()
    i = numpy.arange(e[0], e[1] + 1)[None, :]
    j = numpy.arange(e[2], e[3] + 1)[:, None]
    return (((i > e[0]) | (e[0] == 0)) & ((j > e[2]) | (e[2] == 0))).ravel()


def utc_offset_text(minutes):
    sign = "+" if minutes >= 0 else "-"
    return "%s%02d:%02d" % (sign, abs(minutes) // 60, abs(minutes) % 60)


def time_range(args, longitude):
    """(start, end) as ISO 8601 with offsets."""
    if args.utc_offset is not None:
        if not re.fullmatch(r"[+-]\d\d:?\d\d|Z", args.utc_offset):
            raise InputError("--utc-offset %r is not +HH:MM or -HH:MM" % args.utc_offset)
        offset = args.utc_offset
    else:
        offset = utc_offset_text(60 * int(round(longitude / 15.0)))
    if args.day_of_year is not None:
        if args.start or args.end:
            raise InputError("give either --day-of-year or --start/--end, not both")
        days = 366 if (args.year % 4 == 0 and args.year % 100 != 0) or args.year % 400 == 0 else 365
        if not 1 <= args.day_of_year <= days:
            raise InputError("--day-of-year %d is not a day of %d (1..%d)" % (args.day_of_year, args.year, days))
        day = datetime.date(args.year, 1, 1) + datetime.timedelta(days=args.day_of_year - 1)
        return day.isoformat() + "T00:00:00" + offset, (day + datetime.timedelta(days=1)).isoformat() + "T00:00:00" + offset
    if not args.start and args.weather:
        return "%d-01-01T00:00:00%s" % (args.year, offset), "%d-01-01T00:00:00%s" % (args.year + 1, offset)
    if not args.start:
        raise InputError("give --start (and --end) or --day-of-year")

    def instant(text, is_end):
        if re.fullmatch(r"\d{4}-\d\d-\d\d", text):
            try:
                day = datetime.date.fromisoformat(text)
            except ValueError as error:
                raise InputError("%r is not a date: %s" % (text, error))
            if is_end:
                day += datetime.timedelta(days=1)
            return day.isoformat() + "T00:00:00" + offset
        if re.search(r"(Z|[+-]\d\d(:?\d\d)?)$", text.split("T")[-1]):
            return text
        return text + offset
    return instant(args.start, False), instant(args.end or args.start, True)


def linke_values(text):
    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        raise InputError("--linke %r: give one number or twelve comma-separated numbers" % text)
    if len(values) not in (1, 12):
        raise InputError("--linke takes one value or twelve (one per month), not %d" % len(values))
    return values * 12 if len(values) == 1 else values


def run(args):
    # Only the VTK modules used (terralux imports its bases): `import vtk` would load all
    # of VTK, 0.12 s of a daily run.
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    from terralux import vtkSolarIrradiation, vtkTerrainRasterWriter, vtkTerrainSource

    if not os.path.isfile(args.dem):
        raise InputError("no DEM at %s" % args.dem)
    messages = []  # VTK's errors, kept for one-line messages instead of VTK's own

    def observe(algorithm):
        @calldata_type(VTK_STRING)  # the error's text as call data
        def on_error(caller, event, text=None):
            # VTK's text is "file, line\nclass (address): message"; keep the message.
            last = str(text or event).strip().splitlines()[-1]
            messages.append(last.split("): ", 1)[-1])
        algorithm.AddObserver("ErrorEvent", on_error)
        # The executive's "returned failure" follows every error: nothing to add.
        algorithm.GetExecutive().AddObserver("ErrorEvent", lambda caller, event: None)
        return algorithm

    start_clock = time.perf_counter()
    controller = start_mpi() if args.mpi else None
    rank = controller.GetLocalProcessId() if controller else 0
    ranks = controller.GetNumberOfProcesses() if controller else 1
    terrain = observe(vtkTerrainSource())
    terrain.SetFileName(args.dem)
    # With a far terrain each rank reads its piece and a halo of the DEM, and the far
    # terrain whole (every Nth post): checked and georeferenced there, not on the DEM.
    far = args.far_stride > 1 and args.detail_distance > 0.0
    if far:
        terrain.SetFarTerrainStride(args.far_stride)
    checked = 1 if far else 0
    terrain.Update(checked)
    if terrain.GetOutput(checked).GetNumberOfPoints() == 0:
        raise InputError("could not read %s: %s" % (args.dem, messages[-1] if messages else "no terrain"))
    origin = terrain.GetOutput(checked).GetFieldData().GetArray("GeoOrigin")
    if origin is None:
        raise InputError("%s has no georeference (a CRS): TerraLux needs the place to place the sun" % args.dem)
    longitude = origin.GetTuple3(0)[1]  # GeoOrigin: (latitude, longitude, height)
    start, end = time_range(args, longitude)
    if not 0.0 <= args.reflectance < 1.0:
        raise InputError("--reflectance %g is not in [0, 1)" % args.reflectance)
    if not 1 <= args.sky_type <= 15:
        raise InputError("--sky-type %d is not a CIE standard general sky (1..15)" % args.sky_type)
    if args.pieces and not args.output.lower().endswith(".vrt"):
        raise InputError("--pieces writes a VRT over the ranks' GeoTIFFs at -o: give it a .vrt name, not %s"
                         % args.output)
    if not 0.0 <= args.detail_distance < float("inf"):
        raise InputError("--detail-distance %g is not a distance in metres (>= 0; 0: none)" % args.detail_distance)
    if not 1e-6 <= args.target_error <= 1.0:
        raise InputError("--target-error %g is not a fraction of what a post receives (1e-6..1)" % args.target_error)
    if args.target_floor is not None and not 0.0 <= args.target_floor < float("inf"):
        raise InputError("--target-floor %g is not an irradiance in W/m^2 (>= 0)" % args.target_floor)
    if not 0 <= args.seed <= 2**31 - 1:
        raise InputError("--seed %d is not a seed (0..2147483647)" % args.seed)
    if args.far_stride < 1:
        raise InputError("--far-stride %d is not a stride of posts (>= 1; 1: none)" % args.far_stride)
    if args.far_stride > 1 and not args.detail_distance > 0.0:
        raise InputError("--far-stride %d needs --detail-distance M (> 0): rays see the far terrain beyond it"
                         % args.far_stride)

    irradiation = observe(vtkSolarIrradiation())
    irradiation.SetInputConnection(terrain.GetOutputPort())
    irradiation.SetStartTime(start)
    irradiation.SetEndTime(end)
    irradiation.SetTimeStep(args.step)
    irradiation.SetMonthlyLinkeTurbidity(linke_values(args.linke))
    irradiation.SetDefaultReflectance(args.reflectance)
    irradiation.SetIrradianceModel(0 if args.model == "esra" else 1)
    irradiation.SetSkyType(args.sky_type)
    irradiation.SetErrorTolerance(args.tolerance)
    irradiation.SetDetailDistance(args.detail_distance)
    if far:
        irradiation.SetFarTerrainConnection(terrain.GetOutputPort(1))
    irradiation.SetTargetError(args.target_error)
    if args.target_floor is not None:
        irradiation.SetTargetErrorFloor(args.target_floor)
    irradiation.SetRandomSeed(args.seed)
    irradiation.SetPostNormalsToHorn()  # as r.slope.aspect and gdaldem
    if args.weather:
        if not os.path.isfile(args.weather):
            raise InputError("no weather file at %s" % args.weather)
        irradiation.SetWeatherFileName(args.weather)
    bar = None
    if not args.quiet and rank == 0:
        try:
            from tqdm import tqdm
            bar = tqdm(total=100, unit="%", desc="irradiation", leave=False, file=sys.stderr,
                       bar_format="{desc}: {percentage:3.0f}%|{bar}| {elapsed}")
            irradiation.AddObserver("ProgressEvent", lambda caller, event: bar.update(
                round(100 * caller.GetProgress()) - bar.n))
        except ImportError:
            bar = None
    irradiation.UpdatePiece(rank, ranks, 0)  # the whole DEM on one process
    if bar is not None:
        bar.close()
    result = irradiation.GetOutput()
    if result.GetNumberOfPoints() == 0:
        raise InputError(messages[-1] if messages else "the irradiation failed")

    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy
    point_data = result.GetPointData()
    if args.kwh:
        for name in ENERGY_BANDS:
            array = point_data.GetArray(name)
            if array is None:  # IrradiationError: at points only
                continue
            values = vtk_to_numpy(array)
            values /= 1000.0
            array.GetInformation().Set(array.UNITS_LABEL(), "kWh/m^2")
            array.Modified()
    writer = observe(vtkTerrainRasterWriter())
    writer.SetInputData(result)
    writer.SetFileName(args.output)
    writer.SetWritePieces(args.pieces)
    for name in BANDS:
        if point_data.GetArray(name) is not None:
            writer.AddArrayName(name)
    if not writer.Write():  # collective under MPI: rank 0 writes the pieces as one file, or the VRT
        raise InputError("could not write %s: %s" % (args.output, messages[-1] if messages else ""))

    field = result.GetFieldData()
    steps = int(field.GetArray("Steps").GetValue(0))
    hours = field.GetArray("StepHours")
    daylight = sum(hours.GetValue(k) for k in range(hours.GetNumberOfTuples()))
    unit = "kWh/m^2" if args.kwh else "Wh/m^2"
    # Means over the whole DEM: each rank's sums over the posts it owns, added up.
    owned = owned_posts(result)
    sums = {}
    for name in BANDS:
        array = point_data.GetArray(name)
        if array is not None:
            values = vtk_to_numpy(array)[owned]
            finite = numpy.isfinite(values)
            sums[name] = (float(values[finite].sum()), int(finite.sum()))
    if controller:
        from mpi4py import MPI
        sums = {name: tuple(MPI.COMM_WORLD.allreduce(v) for v in pair) for name, pair in sums.items()}
    if rank == 0:
        print("%s: %s to %s, %d daylight steps (%.1f h of sun above the horizon), %.1f s%s" % (
            PROGRAM, start, end, steps, daylight, time.perf_counter() - start_clock,
            ", %d ranks" % ranks if controller else ""))
        for name, (total, count) in sums.items():
            print("  mean %-21s %10.3f %s" % (name, total / max(count, 1), unit if name in ENERGY_BANDS else
                                                 ("h" if name == "SunshineDuration" else "")))
        print("wrote", args.output)


def main(argv=None):
    args = parse_arguments(sys.argv[1:] if argv is None else argv)
    try:
        run(args)
    except InputError as error:
        sys.exit("%s: error: %s" % (PROGRAM, error))
    return 0


if __name__ == "__main__":
    sys.exit(main())
