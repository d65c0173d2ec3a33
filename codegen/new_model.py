"""`python -m codegen new-model NAME --like MODEL`: a new model as a copy of MODEL's folder.

It copies fmu_src/models/MODEL/ (description.py, model.c, the bad-input rows, which hold for the
copy as long as its code is MODEL's) under
the new name, with the name and the C prefix replaced and a new GUID, adds NAME to the model list
(codegen/project.py: MODELS) and regenerates every generated file. `bash scripts/build.sh` then
builds dist/NAME.fmu and dist/fmi3/NAME.fmu (docs/contributing.md says what to change next)."""
import pathlib
import re
import shutil
import uuid

from codegen import models, project

PROJECT_FILE = models.ROOT / "codegen" / "project.py"


def named(name):
    """A pattern of the name as a word of its own or the start of a file or C name
    (EulerRates_variables.h)."""
    return rf"(?<![A-Za-z0-9]){name}(?![A-Za-z0-9])"


def c_prefix_for(name, taken):
    """The C prefix of a new model's generated names: its name's capitals (EulerRates: ER), or
    its whole name in capitals where those are taken by another model."""
    for prefix in ("".join(c for c in name if c.isupper()), name.upper()):
        if len(prefix) >= 2 and prefix not in taken:
            return prefix
    raise SystemExit(f"new-model: no free C prefix for {name} ({', '.join(sorted(taken))} taken)")


def check_arguments(name, like):
    if not re.fullmatch(r"[A-Z][A-Za-z0-9]*", name):
        raise SystemExit(f"new-model: NAME = {name!r} must be a C identifier that starts with a "
                         "capital letter (it is the FMU's model identifier)")
    if like not in project.MODELS:
        raise SystemExit(f"new-model: --like {like!r} is not a model of codegen/project.py "
                         f"({', '.join(project.MODELS)})")
    if name in project.MODELS or (models.MODELS_DIR / name).exists():
        raise SystemExit(f"new-model: {name} exists already")


def copy_description(source, target, name, like, prefix):
    """description.py with the new name, C prefix and GUID; the rest as the model it is like."""
    text = (source / "description.py").read_text()
    old = models.load(like)
    replacements = [
        (f'NAME = "{like}"', f'NAME = "{name}"'),
        (f'C_PREFIX = "{old.c_prefix}"', f'C_PREFIX = "{prefix}"'),
        (f'GUID = "{old.guid}"', f'GUID = "{{{uuid.uuid4()}}}"'),
    ]
    for before, after in replacements:
        if before not in text:
            raise SystemExit(f"new-model: {source / 'description.py'} has no line {before}")
        text = text.replace(before, after, 1)
    text = re.sub(rf'\A"""{named(like)}', f'"""{name}', text)
    (target / "description.py").write_text(text)
    return old


def copy_files(source, target, name, like, old_prefix, prefix):
    """Every other file of the folder (model.c, the bad-input rows, the generated files, which
    codegen then writes anew) with the model's name
    and C prefix replaced, in the file names too."""
    for path in sorted(source.rglob("*")):
        relative = path.relative_to(source)
        if (path.is_dir() or relative == pathlib.Path("description.py") or
                "__pycache__" in relative.parts):
            continue
        out = target / re.sub(named(like), name, str(relative))
        out.parent.mkdir(parents=True, exist_ok=True)
        text = re.sub(named(like), name, path.read_text())
        out.write_text(re.sub(rf"(?<![A-Za-z0-9_]){old_prefix}_", f"{prefix}_", text))


def add_to_model_list(name):
    """codegen/project.py's MODELS with the new name at the end."""
    text = PROJECT_FILE.read_text()
    match = re.search(r"^MODELS = \[([^\]]*)\]", text, flags=re.MULTILINE)
    if match is None:
        raise SystemExit(f"new-model: {PROJECT_FILE} has no line MODELS = [...]")
    listed = match.group(1).rstrip()
    text = text[:match.start(1)] + f'{listed}, "{name}"' + text[match.end(1):]
    PROJECT_FILE.write_text(text)
    project.MODELS.append(name)


def new_model(name, like):
    check_arguments(name, like)
    source, target = models.MODELS_DIR / like, models.MODELS_DIR / name
    taken = {models.load(m).c_prefix for m in project.MODELS}
    prefix = c_prefix_for(name, taken)
    target.mkdir()
    try:
        old = copy_description(source, target, name, like, prefix)
        copy_files(source, target, name, like, old.c_prefix, prefix)
    except BaseException:
        shutil.rmtree(target)
        raise
    add_to_model_list(name)
    print(f"new-model: fmu_src/models/{name}/ from {like} (C prefix {prefix}), added to "
          f"codegen/project.py MODELS")
