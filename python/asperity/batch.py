"""asperity.batch: many measured surfaces analysed on a Dask cluster into one table.

A production line measures thousands of parts; each file gets the whole analysis of
asperity.topography.analyse_surface_file, run on the workers of a dask.distributed cluster (a
LocalCluster on this machine by default, or a running scheduler's address), and the batch gives one
table -- a row per surface: statistics, fits, verdict, contact ratios -- plus each surface's JSON
document (schema asperity.topography.SURFACE_JSON_SCHEMA):

    from asperity import batch
    if __name__ == "__main__":  # required in a script: the worker processes import it again
        rows = batch.analyse_files(paths, "results", contact_modulus=1.1e11)
        # results/surfaces.csv (the table), results/<name>.json (each surface's analysis)

A run can be interrupted at any point and started again: a surface whose JSON was finished with
the same options (and asperity version) is not analysed again, and nothing half-written is ever
taken for a result. Every file is written through the library's output policy (a temporary file in
the same folder, then a rename; never through a planted link, never over a file of another kind); a
surface's <name>.done marker, written after its JSON, records the options' fingerprint,
the JSON's SHA-256 and the input file's size and modification time, and is what makes it finished.
A file that cannot be analysed gives a row with status "failed" and the error, not a failed batch.

The workers must see the input files at the same paths (a shared file system on a real cluster) and
import the same asperity; the JSON documents and the table are written by the calling process only,
so the output folder needs to be visible to it alone. One run at a time per output folder (a lock).
dask and distributed are imported by analyse_files only: `import asperity` does not need them.
"""
import csv
import hashlib
import io
import json
import os
import re
import sys
import time

__all__ = ["COLUMNS", "analyse_files", "options_fingerprint", "output_name", "read_table", "row_from_json"]

_DONE_SCHEMA = "asperity-batch-done/1"  # a surface's <name>.done marker
# The models' names, spelled once: by the library (the JSON documents' spelling), read from the module.
# The fits' columns spell a height model with underscores (heights_weibull_tail_ad_p), the contact
# columns as the JSON does (stiffness_over_measured_0_weibull-tail).
from ._asperity import topography as _topography  # noqa: E402

_SCHEMA = _topography.SURFACE_JSON_SCHEMA  # the surfaces' JSON documents'

_MODELS = tuple(model.replace("-", "_") for model in _topography.height_model_names)
_SAMPLES = ("summit_heights", "heights")
# the curves of a contact comparison, in the library's order (ContactModelKind)
_MEASURED, _OWN_RADII, _GAUSSIAN_MOMENTS, *_FITTED, _PERSSON, _EXACT = _topography.contact_model_names
# the contact models whose stiffness is compared with GW summed over the measured summits
_CONTACT_MODELS = (_GAUSSIAN_MOMENTS, *_FITTED, _OWN_RADII, _PERSSON, _EXACT)
# the curves compared with the exact contact, when it was solved
_EXACT_MODELS = (_MEASURED,) + _CONTACT_MODELS[:-1]

COLUMNS = [
    "source", "name", "status", "error", "seconds",
    "nx", "ny", "dx_m", "dy_m", "valid_points", "missing_points",
    "Sq_m", "Sa_m", "Ssk", "Sku", "alpha", "anisotropy", "isotropic", "noise_floor_reached",
    "summits", "summit_density_per_m2", "summit_radius_m", "summits_fitted", "surrogates",
    "verdict_tested", "gaussian_rejected",
    "gaussian_p_heights", "gaussian_p_heights_is_bound",
    "gaussian_p_summit_heights", "gaussian_p_summit_heights_is_bound",
    "summit_test_applicable", "heights_orientation", "side_told", "side_note", "model_for_contact",
] + [
    f"{sample}_{model}_{field}"
    for sample in _SAMPLES
    for model in _MODELS
    for field in (("ad_p", "ad_p_is_bound", "akaike_weight") if _topography.parameter_count(model) == 2 else
                  ("shape", "shape_lo", "shape_hi", "shape_identified", "ad_p", "ad_p_is_bound", "akaike_weight"))
] + ["verdict_text", "contact_closest_model", "contact_headline", "contact_closest_to_exact"]
"""The table's fixed columns, in order. With contact curves, each pressure k (0, 1, ...) adds
pressure_{k}_Pa, measured_summits_stiffness_spread_{k}, measured_summits_in_contact_{k} and, for
each model m compared with the measured summits, stiffness_over_measured_{k}_{m}; with the exact contact solved, for each curve m
stiffness_over_exact_{k}_{m} and area_over_exact_{k}_{m}: see row_from_json."""

# Where each fixed column is in a surface's JSON document (SURFACE_JSON_SCHEMA). A column of a result
# record names the record's field: its key in the record's object is the record's own list's
# (asperity.topography.record_fields: the one definition the library writes the document from), so
# a field renamed there is found here, and a field that is not written fails at import, not as an
# empty column. (section of the document, its record type, {column: the record's field})
_RECORD_COLUMNS = (
    ("statistics", _topography.HeightStatistics,
     {"valid_points": "valid_points", "missing_points": "missing_points", "Sq_m": "rms", "Sa_m": "mean_absolute",
      "Ssk": "skewness", "Sku": "kurtosis"}),
    ("spectral_moments", _topography.SpectralMoments, {"alpha": "alpha", "anisotropy": "anisotropy"}),
    ("noise_floor", _topography.NoiseFloor, {"noise_floor_reached": "reached"}),
    ("summits", _topography.Summits, {"summit_density_per_m2": "density", "summit_radius_m": "radius"}),
    ("verdict", _topography.SurfaceVerdict,
     {"verdict_tested": "tested", "gaussian_rejected": "gaussian_rejected", "gaussian_p_heights": "p_heights",
      "gaussian_p_heights_is_bound": "p_heights_bound", "gaussian_p_summit_heights": "p_summits",
      "gaussian_p_summit_heights_is_bound": "p_summits_bound", "summit_test_applicable": "summit_test_applicable",
      "side_told": "side_told", "side_note": "side_note", "verdict_text": "text"}),
)


def _record_key(record, field):
    """The JSON key of a record's field, from the record's list."""
    keys = {name: key for name, key, _ in _topography.record_fields(record)}
    if keys.get(field) is None:
        raise LookupError(f"{record.__name__}.{field} is not written to the JSON document")
    return keys[field]


# The keys a writer composes around a record's fields (not a record's field: a count, a derived
# value, a name that stands for none; summits_fitted and surrogates are SurfaceAnalysis's fields,
# written inside the fits and ensemble objects the writer composes), and the document's own
_COMPOSED_PATHS = {
    **{key: ("surface", key) for key in ("nx", "ny", "dx_m", "dy_m")},
    "isotropic": ("spectral_moments", "isotropic"),
    "summits": ("summits", "count"),
    "summits_fitted": ("fits", "summits_fitted"), "surrogates": ("ensemble", "surrogates"),
    "heights_orientation": ("verdict", "heights_orientation"), "model_for_contact": ("verdict", "model_for_contact"),
}
_JSON_PATHS = {
    **_COMPOSED_PATHS,
    **{column: (section, _record_key(record, field))
       for section, record, columns in _RECORD_COLUMNS for column, field in columns.items()},
}
# a model's fit in fits.*.models[]: its columns' suffix and the field (HeightDistribution's or
# ModelAssessment's) each reads
_MODEL_KEYS = {
    "ad_p": _record_key(_topography.ModelAssessment, "anderson_darling_p"),
    "ad_p_is_bound": _record_key(_topography.ModelAssessment, "p_at_floor"),
    "akaike_weight": _record_key(_topography.ModelAssessment, "akaike_weight"),
    "shape": _record_key(_topography.HeightDistribution, "shape"),
    "shape_identified": _record_key(_topography.ModelAssessment, "shape_identified"),
}
_MODEL_NAME_KEY = _record_key(_topography.HeightDistribution, "model")
# the contact comparison's (contact) and each model's (contact.models[]) keys, from their records' lists
_CONTACT_KEYS = {field: _record_key(_topography.ContactComparison, field)
                 for field in ("pressures", "measured_summits_in_contact", "models", "closest", "headline")}
_MODEL_CONTACT_KEYS = {field: _record_key(_topography.ModelContact, field)
                       for field in ("kind", "served", "at_pressures")}


# ---- options: a plain, picklable description of an AnalysisOptions, and its fingerprint ----

def _options_to_plain(value):
    """A bound options object as nested dicts of its read-write attributes (lists, numbers, strings,
    enums by name), picklable and JSON-able; the inverse is _options_from_plain."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)):
        return [_options_to_plain(v) for v in value]
    cls = type(value)
    if hasattr(cls, "__members__"):  # a bound enum
        return {"__enum__": cls.__name__, "name": value.name}
    fields = {name: _options_to_plain(getattr(value, name))
              for name, attribute in sorted(vars(cls).items())
              if isinstance(attribute, property) and attribute.fset is not None and not name.startswith("_")}
    return {"__type__": cls.__name__, "fields": fields}


def _options_from_plain(plain):
    from . import topography
    if isinstance(plain, list):
        return [_options_from_plain(v) for v in plain]
    if not isinstance(plain, dict):
        return plain
    if "__enum__" in plain:
        return getattr(getattr(topography, plain["__enum__"]), plain["name"])
    cls = getattr(topography, plain["__type__"])
    fields = {name: _options_from_plain(v) for name, v in plain["fields"].items()}
    try:
        made = cls()
    except TypeError:  # a required argument (ContactOptions' contact_modulus)
        made = cls(**fields)
    for name, v in fields.items():
        setattr(made, name, v)
    return made


def _without_threads(plain):
    # thread counts do not change the results (the library's ensembles are reproducible for every
    # thread count), so they are not part of the fingerprint
    if isinstance(plain, list):
        return [_without_threads(v) for v in plain]
    if isinstance(plain, dict):
        return {k: _without_threads(v) for k, v in plain.items() if k != "threads"}
    return plain


def options_fingerprint(options=None) -> str:
    """The SHA-256 (hex) of what decides an analysis's result: every field of the AnalysisOptions
    (None: the defaults) except thread counts, the asperity version and the JSON schema. A finished
    surface is taken over by a later run only if the fingerprints agree."""
    from . import __version__, topography
    plain = options if isinstance(options, dict) else _options_to_plain(
        options if options is not None else topography.AnalysisOptions())
    text = json.dumps({"options": _without_threads(plain), "asperity": __version__, "schema": _SCHEMA},
                      sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def _plain_options(options, *, bootstrap=None, seed=None, confidence=None, significance=None,
                   contact_modulus=None, pressures=None, nominal_area=None, table_path=None, analysis_threads=1):
    from . import topography
    if options is not None and not isinstance(options, topography.AnalysisOptions):
        raise TypeError("options must be an asperity.topography.AnalysisOptions or None")
    plain = _options_to_plain(options if options is not None else topography.AnalysisOptions())
    fields = plain["fields"]
    assessment = fields["assessment"]["fields"]
    for name, value in (("bootstrap", bootstrap), ("seed", seed), ("confidence", confidence),
                        ("significance", significance)):
        if value is not None:
            assessment[name] = value
    if contact_modulus is not None:
        if fields["contact"] is None:
            fields["contact"] = _options_to_plain(topography.ContactOptions(contact_modulus))
        fields["contact"]["fields"]["contact_modulus"] = contact_modulus
    for name, value in (("pressures", pressures), ("nominal_area", nominal_area), ("table_path", table_path)):
        if value is None:
            continue
        if fields["contact"] is None:
            raise ValueError(f"{name} needs the contact curves: give contact_modulus (or options.contact)")
        fields["contact"]["fields"][name] = [float(p) for p in value] if name == "pressures" else (
            os.fsdecode(value) if name == "table_path" else value)
    if analysis_threads is not None:
        assessment["threads"] = int(analysis_threads)
        if fields["contact"] is not None:
            fields["contact"]["fields"]["threads"] = int(analysis_threads)
    # checked here, once, by the library's own constructors (a bad option is an error of the call,
    # not a failed row per file), and read back through them: plain Python numbers (a numpy integer
    # given as the seed fingerprints as the int it is)
    return _options_to_plain(_options_from_plain(plain))


# ---- names and files ----

def output_name(path) -> str:
    """The name of a surface's outputs (<name>.json, <name>.done): the file's stem made safe (letters,
    digits, '.', '_', '-'), then '-' and 10 hex digits of the SHA-256 of its absolute path, so that
    files of one name in different folders do not collide and a name is the same in every run."""
    absolute = os.path.abspath(os.fsencode(path))
    stem = os.path.splitext(os.path.basename(os.fsdecode(absolute)))[0]
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", stem).lstrip(".")[:60] or "surface"
    return f"{stem}-{hashlib.sha256(absolute).hexdigest()[:10]}"


# what a run of an earlier version left when interrupted (this one writes through the library's output
# policy, whose temporaries it removes itself)
_TEMPORARY = re.compile(r"^\..+\.tmp-[0-9a-f]{16}$")


def _write_file(directory, name, data: bytes, kind):
    """data as directory/name through the library's output policy (asperity/output.hpp): a temporary in
    the folder renamed into place, never through a planted link, never over a file of another kind."""
    from ._asperity import _output
    _output.write_file(os.path.join(directory, name), data, kind)


def _remove(path):
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass


def _source_stat(path):
    try:
        st = os.stat(path)
    except OSError:
        return None
    return [st.st_size, st.st_mtime_ns]


class _Lock:
    """One run at a time per output folder (an exclusive lock on <output_dir>/.batch.lock, opened only
    inside the folder and never through a link)."""

    def __init__(self, directory):
        from ._asperity import _output
        self.fd = _output.lock_folder(directory, ".batch.lock")
        if self.fd < 0:
            raise RuntimeError(f"another run is writing into {os.fsdecode(directory)}")

    def release(self):
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


# ---- a script without the main guard ----

_NO_GUARD = ("asperity.batch.analyse_files was called {where} without `if __name__ == \"__main__\":`. Its worker "
             "processes start by importing the main script again (multiprocessing's spawn), so each worker would "
             "start the batch again, and Dask would restart them forever. Put the call under "
             "`if __name__ == \"__main__\":` (docs/surfaces.md).")


def _in_main_guard(path, line):
    """Whether line of the script at path lies inside an `if __name__ == "__main__":` block (None if the
    script cannot be read)."""
    import ast
    try:
        with open(path, "rb") as f:
            tree = ast.parse(f.read())
    except (OSError, SyntaxError, ValueError):
        return None
    for node in ast.walk(tree):
        if not isinstance(node, ast.If) or not isinstance(node.test, ast.Compare):
            continue
        sides = [node.test.left] + node.test.comparators
        names = {n.id for n in sides if isinstance(n, ast.Name)}
        texts = {n.value for n in sides if isinstance(n, ast.Constant)}
        if "__name__" in names and "__main__" in texts and node.body:
            if node.body[0].lineno <= line <= (node.body[-1].end_lineno or node.body[-1].lineno):
                return True
    return False


def _refuse_unguarded_main(processes, scheduler):
    """Fails at once where worker processes would re-run the batch: in a worker importing the main
    script again (its __main__ is __mp_main__), or in a script calling the batch at its top level
    outside the main guard (checked in its source) while the batch starts a LocalCluster of processes."""
    main = sys.modules.get("__main__")
    if getattr(main, "__name__", None) == "__mp_main__":
        raise RuntimeError(_NO_GUARD.format(where="while a worker process imported the main script"))
    if scheduler is not None or not processes:
        return
    script = getattr(main, "__file__", None)
    frame = sys._getframe(2)
    while frame is not None:
        if frame.f_code.co_name == "<module>" and frame.f_globals.get("__name__") == "__main__":
            if script and os.path.abspath(frame.f_code.co_filename) == os.path.abspath(script) and \
                    _in_main_guard(script, frame.f_lineno) is False:
                raise RuntimeError(_NO_GUARD.format(
                    where=f"at the top level of the script {script} (line {frame.f_lineno})"))
            return
        frame = frame.f_back


# ---- one surface (on a worker) ----

def _analyse_one(path, plain_options):
    """Runs on a worker: the analysis of one file as its JSON text, or the error's message."""
    from . import __version__, topography
    started = time.perf_counter()
    stat = _source_stat(path)
    try:
        analysis = topography.analyse_surface_file(path, _options_from_plain(plain_options))
        text, error = analysis.json(), None
    except Exception as exc:  # noqa: BLE001 -- every error of one file becomes its row
        text, error = None, f"{type(exc).__name__}: {exc}"
    return {"json": text, "error": error, "seconds": time.perf_counter() - started, "source_stat": stat,
            "version": __version__}


# ---- the table's row ----

def _number(value):
    return None if value is None else float(value)


def row_from_json(document, source=None, name=None) -> dict:
    """A surface's row of the table from its JSON document (a str, bytes or the parsed dict): the
    columns of COLUMNS (status "analysed", error None, seconds None: analyse_files fills them) and,
    with contact curves, for each pressure k: pressure_{k}_Pa, measured_summits_stiffness_spread_{k}
    (the relative spread of GW over the measured summits across the ensemble: the uncertainty of the
    ratios), measured_summits_in_contact_{k} (how many measured summits carry that answer: below
    asperity.topography.MIN_SUMMITS_TO_COMPARE no model is named closest there) and
    stiffness_over_measured_{k}_{model} for gaussian-moments, gaussian, weibull-tail,
    weibull-bounded, measured-summits-own-radii, persson and exact (None where a model has no
    curve); with the exact contact solved, stiffness_over_exact_{k}_{model} and
    area_over_exact_{k}_{model} for measured-summits and the others but exact. Missing values (a
    map at its noise floor, no heights fitted) are None."""
    d = json.loads(document) if isinstance(document, (str, bytes)) else document
    if d.get("schema") != _SCHEMA:
        raise ValueError(f"not an {_SCHEMA} document (schema {d.get('schema')!r})")
    row = dict.fromkeys(COLUMNS)
    row.update({"source": source if source is not None else d["surface"]["source"], "name": name,
                "status": "analysed"})
    for column, path in _JSON_PATHS.items():
        value = d
        for key in path:
            value = value.get(key) if isinstance(value, dict) else None
        row[column] = value
    for sample in _SAMPLES:
        fits = d["fits"].get(sample)
        for m in (fits or {}).get("models", []):
            prefix = f"{sample}_{m[_MODEL_NAME_KEY].replace('-', '_')}_"
            if prefix + "ad_p" not in row:
                continue
            for column in ("ad_p", "ad_p_is_bound", "akaike_weight"):
                row[prefix + column] = m[_MODEL_KEYS[column]]
            if prefix + "shape" in row:  # a model with a shape (the Weibulls)
                row[prefix + "shape"] = m[_MODEL_KEYS["shape"]]
                row[prefix + "shape_lo"], row[prefix + "shape_hi"] = m["interval_shape"]
                row[prefix + "shape_identified"] = m[_MODEL_KEYS["shape_identified"]]
    contact = d.get("contact")
    if contact:
        # None where no model is named (too few measured summits in contact at every pressure), as
        # the CSV reads an empty cell back
        row["contact_closest_model"] = contact[_CONTACT_KEYS["closest"]] or None
        row["contact_headline"] = contact[_CONTACT_KEYS["headline"]]
        # the keys the writer composes around the comparison's fields (the references, the spread)
        # and into each model's states at the pressures of interest (its ratios)
        references = contact.get("references", {})
        exact_solved = bool(references.get("exact")) and _models_served(contact, _EXACT)
        row["contact_closest_to_exact"] = references.get("closest_to_exact") or None
        name, served, at_pressures = (_MODEL_CONTACT_KEYS[f] for f in ("kind", "served", "at_pressures"))
        models = {m[name]: m for m in contact[_CONTACT_KEYS["models"]]}
        spread = contact["measured_summits_spread"]["stiffness_relative"]
        in_contact = contact.get(_CONTACT_KEYS["measured_summits_in_contact"], [])
        for k, pressure in enumerate(contact[_CONTACT_KEYS["pressures"]]):
            row[f"pressure_{k}_Pa"] = pressure
            row[f"measured_summits_stiffness_spread_{k}"] = spread[k] if k < len(spread) else None
            row[f"measured_summits_in_contact_{k}"] = in_contact[k] if k < len(in_contact) else None
            for label in _CONTACT_MODELS:
                at = models.get(label, {}).get(at_pressures, [])
                value = at[k].get("stiffness_over_measured_summits") if k < len(at) and models[label][served] else None
                row[f"stiffness_over_measured_{k}_{label}"] = value
            if not exact_solved:
                continue
            for label in _EXACT_MODELS:
                at = models.get(label, {}).get(at_pressures, [])
                is_served = k < len(at) and models[label][served]
                row[f"stiffness_over_exact_{k}_{label}"] = at[k].get("stiffness_over_exact") if is_served else None
                row[f"area_over_exact_{k}_{label}"] = at[k].get("area_over_exact") if is_served else None
    return row


def _models_served(contact, label):
    """Whether the contact block holds a served curve of that label."""
    name, served = _MODEL_CONTACT_KEYS["kind"], _MODEL_CONTACT_KEYS["served"]
    return any(m[name] == label and m[served] for m in contact[_CONTACT_KEYS["models"]])


def _failed_row(source, name, error, seconds=None):
    row = dict.fromkeys(COLUMNS)
    row.update({"source": source, "name": name, "status": "failed", "error": error, "seconds": seconds})
    return row


# ---- resuming ----

def _finished(directory, name, source, fingerprint):
    """The row of a surface finished by an earlier run with these options, or None (then it is
    analysed again): its marker names the same source and fingerprint, the JSON's SHA-256 matches
    the marker's, and the input file (where this process sees it) has the size and time recorded."""
    try:
        with open(os.path.join(directory, name + ".done"), "rb") as f:
            done = json.loads(f.read())
        if done.get("fingerprint") != fingerprint or done.get("source") != source:
            return None
        with open(os.path.join(directory, name + ".json"), "rb") as f:
            data = f.read()
        if hashlib.sha256(data).hexdigest() != done.get("json_sha256"):
            return None
        stat = _source_stat(source)
        if stat is not None and done.get("source_stat") != stat:
            return None
        row = row_from_json(data, source, name)
    except (OSError, ValueError, KeyError, TypeError, IndexError):
        return None
    row["status"] = "resumed"
    row["seconds"] = done.get("seconds")
    return row


# ---- progress ----

def _duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return f"{seconds} s"
    if seconds < 3600:
        return f"{seconds // 60} min {seconds % 60:02d} s"
    return f"{seconds // 3600} h {seconds % 3600 // 60:02d} min"


class _Progress:
    """On stderr: surfaces done, failed, resumed, and the time left estimated from this run's
    rate; rewritten in place on a terminal, a line every 10 s otherwise."""

    def __init__(self, enabled, total, resumed):
        self.enabled, self.total, self.resumed = enabled, total, resumed
        self.done = self.failed = 0
        self.started = self.last = time.monotonic()
        self.tty = enabled and sys.stderr.isatty()

    def update(self, failed):
        self.done += 1
        self.failed += failed
        now = time.monotonic()
        if self.enabled and self.resumed + self.done < self.total and (self.tty or now - self.last >= 10.0):
            self._show(now, "")

    def finish(self):
        if self.enabled:
            self._show(time.monotonic(), "\n")

    def _show(self, now, end):
        self.last = now
        to_do = self.total - self.resumed
        elapsed = now - self.started
        text = f"asperity batch: {self.resumed + self.done}/{self.total} surfaces"
        details = [f"{n} {what}" for n, what in ((self.failed, "failed"), (self.resumed, "resumed")) if n]
        if details:
            text += " (" + ", ".join(details) + ")"
        text += f", {_duration(elapsed)}"
        if 0 < self.done < to_do:
            text += f", about {_duration(elapsed / self.done * (to_do - self.done))} left"
        sys.stderr.write(("\r\033[K" if self.tty else "") + text + (end if self.tty else "\n"))
        sys.stderr.flush()


# ---- the batch ----

def _csv_text(rows, columns):
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=columns, extrasaction="ignore", lineterminator="\n")
    writer.writeheader()
    for row in rows:
        writer.writerow({k: ("" if v is None else repr(v) if isinstance(v, float) else v) for k, v in row.items()})
    return out.getvalue()


def read_table(path) -> list:
    """The rows of a surfaces.csv written by analyse_files, numbers as float or int, true/false as
    bool, empty cells as None (a convenience for a table read back without pandas)."""
    def value(text):
        if text == "":
            return None
        if text in ("True", "False"):
            return text == "True"
        try:
            return int(text)
        except ValueError:
            pass
        try:
            return float(text)
        except ValueError:
            return text
    with open(path, newline="", encoding="utf-8") as f:
        return [{k: (v or None if k in ("source", "name", "error") else value(v)) for k, v in row.items()}
                for row in csv.DictReader(f)]


def _columns(rows):
    extra = []  # the per-pressure columns, in the order row_from_json makes them
    for row in rows:
        extra += [k for k in row if k not in COLUMNS and k not in extra]
    return COLUMNS + extra


def analyse_files(paths, output_dir, options=None, *, bootstrap=None, seed=None, confidence=None,
                  significance=None, contact_modulus=None, pressures=None, nominal_area=None, table_path=None,
                  scheduler=None, n_workers=None, threads_per_worker=None, processes=True, analysis_threads=1,
                  progress=True, resume=True):
    """Analyses every file of paths on a Dask cluster; returns the table, a row (dict) per distinct
    file in the order given, and writes it to output_dir/surfaces.csv, each surface's JSON document
    to output_dir/<name>.json (name: output_name(path)).

    options: an asperity.topography.AnalysisOptions (None: the defaults); bootstrap, seed,
    confidence, significance (of the ensembles' tests), contact_modulus [Pa] (turns the contact
    curves on), pressures [Pa], nominal_area [m^2] and table_path override its fields.
    scheduler: None for a dask.distributed LocalCluster on this machine (n_workers worker
    processes, or threads with processes=False, threads_per_worker threads each; default: a
    worker per core, one thread each), a scheduler's address ("tcp://host:8786") for a running
    cluster, or a distributed.Client. analysis_threads: threads of each file's analysis (1: the
    files are the parallelism; 0: every core of the worker; the results do not depend on it).
    progress: a progress line with the time left on stderr. resume: take over the surfaces an
    earlier run finished with the same options_fingerprint (False: analyse every file again).

    Row columns: COLUMNS (and the per-pressure contact ratios, see row_from_json); status is
    "analysed", "resumed" (finished by an earlier run) or "failed" (error holds the message; no
    JSON). Raises TypeError or asperity.Error for bad options, RuntimeError if another run holds
    output_dir, OSError if output_dir cannot be written; a file's own failure is only its row."""
    _refuse_unguarded_main(processes, scheduler)
    plain = _plain_options(options, bootstrap=bootstrap, seed=seed, confidence=confidence,
                           significance=significance, contact_modulus=contact_modulus, pressures=pressures,
                           nominal_area=nominal_area, table_path=table_path, analysis_threads=analysis_threads)
    fingerprint = options_fingerprint(plain)
    if isinstance(paths, (str, bytes, os.PathLike)):
        raise TypeError("paths must be a list of paths, not one path")
    sources, names, seen = [], [], set()
    for path in paths:
        name = output_name(path)
        if name not in seen:  # a file listed twice is analysed once
            seen.add(name)
            sources.append(os.fsdecode(os.path.abspath(os.fsencode(path))))
            names.append(name)
    directory = os.fsdecode(output_dir)
    os.makedirs(directory, exist_ok=True)
    lock = _Lock(directory)
    try:
        for entry in os.listdir(directory):  # what an interrupted run was writing
            if _TEMPORARY.match(entry):
                _remove(os.path.join(directory, entry))
        rows = [(_finished(directory, name, source, fingerprint) if resume else None)
                for source, name in zip(sources, names)]
        to_do = [k for k, row in enumerate(rows) if row is None]
        report = _Progress(progress, len(rows), len(rows) - len(to_do))
        if to_do:
            _run(to_do, sources, names, rows, plain, directory, fingerprint, report, scheduler=scheduler,
                 n_workers=n_workers, threads_per_worker=threads_per_worker, processes=processes)
        report.finish()
        _write_file(directory, "surfaces.csv",
                    _csv_text(rows, _columns(rows)).encode("utf-8", errors="backslashreplace"), "results_csv")
    finally:
        lock.release()
    return rows


def _run(to_do, sources, names, rows, plain, directory, fingerprint, report, *, scheduler, n_workers,
         threads_per_worker, processes):
    from distributed import Client, LocalCluster, as_completed

    cluster = client = None
    try:
        if scheduler is None:
            workers = n_workers if n_workers is not None else max(1, min(os.cpu_count() or 1, len(to_do)))
            cluster = LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker or 1,
                                   processes=processes, dashboard_address=None)
            client = Client(cluster)
        elif isinstance(scheduler, (str, bytes)):
            client = Client(os.fsdecode(scheduler))
        else:
            client = scheduler  # a distributed.Client given by the caller: left open
        for k in to_do:  # the markers go first: a surface being redone is never finished
            _remove(os.path.join(directory, names[k] + ".done"))
        futures = {}
        for k in to_do:
            futures[client.submit(_analyse_one, sources[k], plain, pure=False)] = k
        for future in as_completed(futures):
            k = futures.pop(future)
            try:
                result = future.result()
            except Exception as exc:  # noqa: BLE001 -- a worker lost on this file, a task cancelled
                result = {"json": None, "error": f"{type(exc).__name__}: {exc}", "seconds": None,
                          "source_stat": None}
            future.release()
            rows[k] = _store(directory, names[k], sources[k], fingerprint, result)
            report.update(rows[k]["status"] == "failed")
    finally:
        if client is not None and client is not scheduler:
            client.close()
        if cluster is not None:
            cluster.close()


def _store(directory, name, source, fingerprint, result):
    from . import __version__
    json_path = os.path.join(directory, name + ".json")
    if result["error"] is None and result.get("version") != __version__:
        result = dict(result, json=None, error=f"the worker runs asperity {result.get('version')}, this process "
                                               f"{__version__}: results of another version are not mixed in")
    if result["error"] is not None:
        _remove(json_path)  # an earlier run's analysis of what this file was
        return _failed_row(source, name, result["error"], result["seconds"])
    data = result["json"].encode("utf-8")
    try:
        row = row_from_json(data, source, name)
    except (ValueError, KeyError, TypeError, IndexError) as exc:
        _remove(json_path)
        return _failed_row(source, name, f"the analysis's JSON is not readable: {type(exc).__name__}: {exc}",
                           result["seconds"])
    row["seconds"] = result["seconds"]
    from . import Error
    try:
        _write_file(directory, name + ".json", data, "results_json")
    except Error as exc:  # a file of another kind in the way (the policy never replaces it)
        return _failed_row(source, name, f"Error: {exc}", result["seconds"])
    # the schema first: the marker is recognised as asperity's JSON results (the output policy)
    done = {"schema": _DONE_SCHEMA, "source": source, "fingerprint": fingerprint,
            "json_sha256": hashlib.sha256(data).hexdigest(), "source_stat": result["source_stat"],
            "seconds": result["seconds"], "finished": time.strftime("%Y-%m-%dT%H:%M:%S%z")}
    _write_file(directory, name + ".done", (json.dumps(done, indent=1) + "\n").encode(), "results_json")
    return row
