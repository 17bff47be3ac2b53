"""Orb from Python: scenes of spheres from files or numpy arrays (docs/python.md).

The module binds Orb's libraries (pybind11, orb._orb); it never runs the tools.
The display through OpenImageIO and OpenColorIO (Image.to_srgb, to_srgb8, png)
is orb._image, imported on its first use, so that the rest needs neither.
Keyword options are orb-import's long options with ``_`` for ``-``
(``orb.load("cloud.ply", color_by="temperature", radius=0.01)``) and are checked
by the same code, with the same messages.
"""

import warnings as _warnings

import numpy as _np

from . import _orb
from ._orb import Camera, Error, Image, Scene, devices

__all__ = ["Camera", "Error", "Image", "Scene", "devices", "frames", "from_ase", "from_mdanalysis", "load", "show"]


def _option_word(value):
    """A keyword's value as the command line writes it; None: a flag."""
    if isinstance(value, (str, bytes)):
        return value.decode() if isinstance(value, bytes) else value
    if isinstance(value, (bool, _np.bool_)):
        raise AssertionError("flags are handled by _keyword_options")
    if isinstance(value, _np.ndarray) or isinstance(value, (list, tuple)):
        return ",".join(_option_word(v) for v in _np.asarray(value).ravel().tolist())
    if isinstance(value, (float, _np.floating)):
        return repr(float(value))
    return str(value)


def _keyword_options(options):
    """[(name, value word or None)]: True is a flag given; False and None leave an option out."""
    words = []
    for name, value in options.items():
        if value is None or value is False or (isinstance(value, _np.bool_) and not value):
            continue
        words.append((name, None if value is True or isinstance(value, _np.bool_) else _option_word(value)))
    return words


def _warn(messages):
    for message in messages:
        _warnings.warn(message, stacklevel=3)


def load(path, **options):
    """Reads any scene Orb reads (orb-import --list-formats) as orb-import does.

    ``options`` are orb-import's options by their long names with ``_``:
    ``color_by``, ``colormap``, ``radius``, ``frame``, ``environment``,
    ``look_at``, ``auto_camera=True``, ... What orb-import would warn about is a
    Python warning. Raises FileNotFoundError, ValueError (a bad option) or
    orb.Error (a bad file) with orb-import's message.
    """
    import os

    scene, messages = Scene._load(os.fspath(path), _keyword_options(options))
    _warn(messages)
    return scene


def _from_arrays(centers, radii, colors=None, materials=None, properties=None):
    """A scene of spheres from arrays: centers (N, 3), radii (N,) or a number.

    colors: None or (N, 3) display (sRGB-encoded) values in [0, 1], as
    matplotlib's. materials: None (a grey diffuse material), a preset
    ("matte", "plastic", "metal") or a dict of the scene format's material keys
    (type, color, emission, ior, roughness, metallic) for every sphere.
    properties: {name: (N,) numbers, or (N,) strings for a category}, for
    ``load``'s colour and radius options' counterparts in orb-import.
    The camera and two lights are placed as for a PLY point cloud.
    """
    listed = []
    for name, values in (properties or {}).items():
        array = _np.asarray(values)
        if array.dtype.kind in "USO":
            labels, indices = _np.unique(array.astype(str), return_inverse=True)
            listed.append((str(name), indices.astype(_np.float64), [str(label) for label in labels]))
        else:
            listed.append((str(name), array, []))
    # One radius for every sphere may come as a numpy number (np.float32(1), or
    # a 0-d array from a reduction), as it may as a Python one.
    if isinstance(radii, _np.generic) or (isinstance(radii, _np.ndarray) and radii.ndim == 0):
        radii = radii.item()
    return Scene._from_arrays(centers, radii, colors, materials, listed)


def _set_camera(self, **options):
    """Changes the camera by orb-import's camera options: camera_position, look_at,
    up, vfov, aperture, focus_distance, orthographic, perspective=True,
    auto_camera=True (frames the spheres anew for the scene's image)."""
    self._set_camera(_keyword_options(options))


def _set_environment(self, value, intensity=1.0, rotation=0.0):
    """Lights the scene from infinitely far away, as --environment does: an
    (R, G, B) radiance, one number, an OpenEXR map's path, or None for none."""
    if value is None:
        self._set_environment([])
        return
    self._set_environment(
        _keyword_options({"environment": value, "environment_intensity": intensity, "environment_rotation": rotation})
    )


Scene.from_arrays = staticmethod(_from_arrays)
Scene.set_camera = _set_camera
Scene.set_environment = _set_environment


def _save(self, path):
    """Writes the scene: a .json name the Orb JSON scene, a .orb name its binary
    form (for millions of spheres), as orb-import writes them; a previous file
    survives any failure."""
    import os

    self._save(os.fspath(path))


Scene.save = _save


def _render(self, width, height, spp, seed=0, device="default", passes=("beauty",), denoise=False,
            target_error=None, noise_threshold=None, time_limit=None, progress=None):
    """Renders the scene as ``orb-render scene.orb --width W --height H --spp N --seed S`` does,
    the same pixels bit for bit, and returns an orb.Image.

    passes: orb-render's --passes names (beauty, albedo, normal, depth, ...).
    progress: None, or a function called after every pass with a dict (pass,
    spp, target_spp, elapsed_seconds, samples_per_second); returning False stops
    the render after that pass (the image then holds what was rendered).
    Ctrl-C (KeyboardInterrupt) stops it the same way and raises. The GIL is
    released while the devices render.
    """
    return _orb._render(self, *_render_arguments(width, height, spp, seed, device, passes, denoise, target_error,
                                                  noise_threshold, time_limit), progress)


def _render_arguments(width, height, spp, seed, device, passes, denoise, target_error, noise_threshold, time_limit):
    """The arguments render and render_progressive share, checked with orb-render's ranges and messages."""
    for option, value, highest in (("--width", width, 65536), ("--height", height, 65536), ("--spp", spp, 2147483647)):
        if not isinstance(value, (int, _np.integer)) or isinstance(value, bool) or not 1 <= value <= highest:
            raise ValueError(f"{option}: Value {value} not in range 1 to {highest}")
    if isinstance(passes, str):
        passes = (passes,)
    return (int(width), int(height), int(spp), seed, str(device), list(passes), bool(denoise), target_error,
            noise_threshold, time_limit)


def _render_progressive(self, width, height, spp, seed=0, device="default", passes=("beauty",), denoise=False,
                        target_error=None, noise_threshold=None, time_limit=None, every=1.0, every_passes=None):
    """Renders as ``render`` does with the same arguments, yielding orb.Image
    objects as the film converges: the image of the first pass, then one every
    ``every`` seconds (or every ``every_passes`` passes), each the mean of the
    samples so far (``image.spp``, ``image.final`` False), and last the
    render's own image, bit for bit ``render``'s (``image.final`` True).

    The render runs on a thread of its own from this call on and never waits
    for the loop: a loop body slower than ``every`` sees fewer images, always
    the newest. Leaving the loop early (``break``, ``close()``) stops the
    render after the pass in flight; Ctrl-C stops it and raises
    KeyboardInterrupt. Errors of the scene or device come from the first
    ``next()``, bad arguments from this call.
    """
    arguments = _render_arguments(width, height, spp, seed, device, passes, denoise, target_error, noise_threshold,
                                  time_limit)
    if every_passes is not None:
        if not isinstance(every_passes, (int, _np.integer)) or isinstance(every_passes, bool) or every_passes < 1:
            raise ValueError(f"every_passes: expected a whole number >= 1, got {every_passes!r}")
        every_seconds, every_passes = 0.0, int(every_passes)
    else:
        if isinstance(every, bool) or not isinstance(every, (int, float, _np.integer, _np.floating)) or \
                not 0 < every < float("inf"):
            raise ValueError(f"every: expected seconds > 0, got {every!r}")
        every_seconds, every_passes = float(every), 0
    return _images_of(_orb._render_progressive(self, *arguments, every_seconds, every_passes))


def _images_of(render):
    """A generator over a progressive render's images; closing it stops the render."""
    try:
        while True:
            image = render.next()
            if image is None:
                return
            yield image
    finally:
        render.close()


Scene.render = _render
Scene.render_progressive = _render_progressive


def _ocio_config():
    import os

    return os.path.join(os.path.dirname(__file__), "ocio", "config.ocio")


def _image_module(function):
    """orb._image, the display through OpenImageIO and OpenColorIO, imported on
    the first call that needs it so that ``import orb``, rendering and EXR
    files need neither; where it cannot load, ``function`` raises ImportError
    saying what is missing."""
    try:
        from . import _image
    except ImportError as missing:
        raise ImportError(
            f"orb.Image.{function} needs orb._image, Orb's display module (OpenImageIO and OpenColorIO), "
            f"which cannot be imported here: {missing}. Rendering, the layers as arrays and Image.save "
            "(OpenEXR) work without it; orb-tonemap shows a saved EXR where those libraries are installed."
        ) from missing
    return _image


def _layer(self, name):
    try:
        return self[name]
    except KeyError:
        raise AttributeError(name) from None


def _to_srgb(self, layer="beauty"):
    """The layer as orb-tonemap shows it by default: opaque, through the default
    display view of Orb's OpenColorIO config ($OCIO wins, as in the tools):
    display-encoded float32 (H, W, 3), not clipped to [0, 1]."""
    return _display(self, layer, "to_srgb", eight_bit=False)


def _to_srgb8(self, layer="beauty"):
    """The same as uint8 (H, W, 3): the values orb-tonemap writes to an 8-bit PNG."""
    return _display(self, layer, "to_srgb8", eight_bit=True)


def _display(image, layer, function, eight_bit):
    """The layer through orb._image's display, for the Image method ``function``."""
    module = _image_module(function)
    shown = module.display8 if eight_bit else module.display
    return shown(image[layer], image.channels(layer), layer, _ocio_config())


def _png_bytes(rgb8):
    """A PNG of an (H, W, 3 or 4) uint8 array (zlib, no other dependency)."""
    import struct
    import zlib

    height, width, channels = rgb8.shape
    color_type = {3: 2, 4: 6}[channels]
    raw = b"".join(b"\x00" + rgb8[row].tobytes() for row in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")


def _repr_png(self):
    """The beauty as orb-tonemap's PNG shows it (Jupyter displays an image by this)."""
    return _png_bytes(_display(self, "beauty", "png", eight_bit=True))


def _save_image(self, path):
    """Writes the EXR file orb-render writes for this render (the same bytes
    but for orb:renderSeconds and orb:device), through a temporary file."""
    import os

    self._save_exr(os.fspath(path))


Image.__getattr__ = _layer
Image.to_srgb = _to_srgb
Image.to_srgb8 = _to_srgb8
Image._repr_png_ = _repr_png
Image.png = _repr_png
Image.save = _save_image


def show(scene, width=320, height=240, spp=16, every=0.5, **options):
    """Renders `scene` small and shows it converging in one notebook cell
    (IPython.display, updated every ``every`` seconds); returns the final
    orb.Image. Outside IPython it renders once and returns the image.
    ``options`` are ``render``'s (seed, device, passes, ...)."""
    try:
        from IPython import get_ipython
        from IPython.display import display
    except ImportError:
        get_ipython = None
    if get_ipython is None or get_ipython() is None:
        return scene.render(width, height, spp, **options)
    shown = None
    for image in scene.render_progressive(width, height, spp, every=every, **options):
        if shown is None:
            shown = display(image, display_id=True)
        else:
            shown.update(image)
    return image


def _extended_xyz(symbols, positions, cell=None, pbc=None, columns=()):
    """One frame as extended XYZ text, the format Orb's XYZ importer reads.
    columns: (name, "S", "I" or "R", values) for more per-atom columns, which
    the importer keeps as properties of that name."""
    positions = _np.asarray(positions, dtype=_np.float64)
    properties = "species:S:1:pos:R:3" + "".join(f":{name}:{kind}:1" for name, kind, _ in columns)
    header = f"Properties={properties}"
    if cell is not None and _np.any(cell):
        lattice = " ".join(repr(float(v)) for v in _np.asarray(cell, dtype=_np.float64).ravel())
        flags = " ".join("T" if p else "F" for p in (pbc if pbc is not None else (True, True, True)))
        header = f'Lattice="{lattice}" {header} pbc="{flags}"'
    lines = _np.asarray(symbols, dtype=str)
    numbers = _np.char.mod("%.17g", positions)
    words = [numbers[:, 0], numbers[:, 1], numbers[:, 2]]
    for _, kind, values in columns:
        values = _np.asarray(values)
        words.append(values.astype(str) if kind == "S" else _np.char.mod("%d" if kind == "I" else "%.17g", values))
    for column in words:
        lines = _np.char.add(_np.char.add(lines, " "), column)
    return f"{len(positions)}\n{header}\n" + "\n".join(lines.tolist()) + "\n"


def _scene_of_xyz(source, text, options, frame=None):
    """The scene Orb reads from extended XYZ text, with ``load``'s options;
    ``frame`` picks a frame of several (the adapters' trajectories)."""
    options = dict(options, **{"from": "xyz"})
    if frame is not None:
        options["frame"] = frame
    scene, messages = Scene._load_text(source, text, _keyword_options(options))
    if frame is not None:  # the importer's note that the text holds several frames is the adapter's own doing
        messages = [m for m in messages if not m.startswith(f"{source}: holds ")]
    _warn(messages)
    return scene


def from_ase(atoms, **options):
    """An ASE Atoms object as Orb reads the same atoms from an extended XYZ file:
    a sphere per atom coloured and sized by element, with ``load``'s options
    (``cell=True`` draws the cell, ``color_by=...``). ASE itself is not needed
    to call it, only an object with ASE's Atoms methods."""
    try:
        symbols, positions = atoms.get_chemical_symbols(), atoms.get_positions()
    except AttributeError:
        raise TypeError("from_ase: expected an ase.Atoms (get_chemical_symbols, get_positions)") from None
    cell = atoms.get_cell() if hasattr(atoms, "get_cell") else None
    pbc = atoms.get_pbc() if hasattr(atoms, "get_pbc") else None
    text = _extended_xyz(symbols, positions, None if cell is None else _np.asarray(cell), pbc)
    return _scene_of_xyz("<ase.Atoms>", text, options)


_MDANALYSIS_SOURCE = "<MDAnalysis AtomGroup>"


def _atom_group(atoms, function):
    """An MDAnalysis AtomGroup: the one given, or a Universe's atoms."""
    group = getattr(atoms, "atoms", None)
    if group is None or not hasattr(group, "positions") or not hasattr(group, "universe"):
        raise TypeError(f"{function}: expected an MDAnalysis Universe or AtomGroup")
    return group


def _guessed_element(name):
    """The element MDAnalysis guesses from an atom name (its guesser moved in MDAnalysis 2.8)."""
    try:
        from MDAnalysis.topology.guessers import guess_atom_element
    except ImportError:
        from MDAnalysis.guesser.default_guesser import DefaultGuesser

        guess_atom_element = DefaultGuesser(None).guess_atom_element
    return guess_atom_element(name)


def _mdanalysis_xyz(group):
    """The group's atoms at the trajectory's current frame as extended XYZ text,
    with the columns Orb's PDB importer keeps as properties, where the topology has them."""
    names = _np.asarray(group.names, dtype=str) if hasattr(group, "names") else None
    elements = _np.asarray(group.elements, dtype=str) if hasattr(group, "elements") else None
    if elements is None:
        if names is None:
            raise ValueError("from_mdanalysis: the topology has neither elements nor atom names")
        elements = _np.array([_guessed_element(n) for n in names], dtype=str)
    elif names is not None and not _np.all(_np.char.strip(elements) != ""):
        blank = _np.char.strip(elements) == ""
        elements = elements.astype("<U3")  # room for a guessed symbol
        elements[blank] = [_guessed_element(n) for n in names[blank]]
    elements = _np.where(_np.char.strip(elements) == "", "X", elements)

    def words(attribute):
        # A categorical column when every atom has a word (extended XYZ separates columns by spaces).
        if not hasattr(group, attribute):
            return None
        values = _np.asarray(getattr(group, attribute), dtype=str)
        if values.size and all(v and not any(c.isspace() for c in v) for v in values.tolist()):
            return values
        return None

    columns = []
    chains = words("chainIDs")
    if chains is None:
        chains = words("segids")
    for name, kind, values in (("chain", "S", chains), ("residue_name", "S", words("resnames")),
                               ("residue_number", "I", group.resids if hasattr(group, "resids") else None),
                               ("atom_name", "S", words("names")),
                               ("b_factor", "R", group.tempfactors if hasattr(group, "tempfactors") else None),
                               ("occupancy", "R", group.occupancies if hasattr(group, "occupancies") else None)):
        if values is not None:
            columns.append((name, kind, values))
    cell = None
    dimensions = group.dimensions
    if dimensions is not None and _np.all(_np.asarray(dimensions[:3]) > 0):
        from MDAnalysis.lib.mdamath import triclinic_vectors

        cell = triclinic_vectors(dimensions)
    return _extended_xyz(elements, group.positions, cell, None, columns)


def from_mdanalysis(atoms, **options):
    """An MDAnalysis Universe or AtomGroup at its trajectory's current frame, as
    Orb reads the same atoms from a molecular file: a sphere per atom coloured
    and sized by element (MDAnalysis's elements, else its guess from the atom
    names), the box as the cell (``cell=True`` draws it), the topology's chain,
    residue_name, residue_number, atom_name, b_factor and occupancy as
    properties for ``color_by``, with ``load``'s options."""
    return _scene_of_xyz(_MDANALYSIS_SOURCE, _mdanalysis_xyz(_atom_group(atoms, "from_mdanalysis")), options)


def frames(atoms, start=None, stop=None, step=None, **options):
    """One Scene per frame of an MDAnalysis trajectory (``trajectory[start:stop:step]``),
    each as ``from_mdanalysis`` makes it, but with the camera and lights of the
    first frame, as ``orb-render --frames`` renders a trajectory: a video of
    them holds still."""
    group = _atom_group(atoms, "frames")
    if "frame" in options:
        raise TypeError("frames() got an unexpected keyword argument 'frame'")
    first = None
    for _ in group.universe.trajectory[start:stop:step]:
        text = _mdanalysis_xyz(group)
        if first is None:
            first = text
            yield _scene_of_xyz(_MDANALYSIS_SOURCE, text, options)
        else:
            # Frame 2 of (first frame, this frame): the importer keeps the first frame's view.
            yield _scene_of_xyz(_MDANALYSIS_SOURCE, first + text, options, frame=2)
