"""output_places - where the study scripts (sweep.sh, the study.sh scripts) may put their results
folder, pages and plots, and files found under another name (a hard link) inside a folder: a
page named after a scene, or a stream appended through a hard link to a point's JSON, would
overwrite a file the run reads (docs/experiments.md, the output rules of the Python tools)."""
import os
import stat

from output_files import _identity, named_files, shown
from output_rules import _through_stream


def inside(path, folder):
    """True when PATH (existing or not) is FOLDER or lies in it at any depth, both with their links
    followed as far as they exist (../, // and a linked folder are the same place)."""
    real, top = os.path.realpath(path), os.path.realpath(folder)
    return real == top or real.startswith(top.rstrip(os.sep) + os.sep)


def linked_into(st, folders, other_than=None):
    """The first of FOLDERS ((option, path) pairs) holding, at any depth, a hard link to the file
    whose os.stat is ST (but the file OTHER_THAN, a real path), else None. Only a file with more
    than one link can have another name, so the usual file (one link) costs no walk."""
    if st is None or not stat.S_ISREG(st.st_mode) or st.st_nlink < 2:
        return None
    key = (st.st_dev, st.st_ino)
    for option, folder in folders:
        for here, _, files in os.walk(folder, onerror=lambda e: None):
            for name in files:
                path = os.path.join(here, name)
                try:
                    other = os.stat(path, follow_symlinks=False)
                except OSError:
                    continue
                if (other.st_dev, other.st_ino) == key and os.path.realpath(path) != other_than:
                    return option, folder
    return None


def _results_place(option, path, repo):
    """Why the results folder PATH may not be used, or None: not in REPO's scenes/, machines/,
    timing/ (the run's inputs) or docs/ (the tree's pages), nor in experiments/ (the code) but in
    a folder named results* there, as the scripts' own are (experiments/results-quick)."""
    real = os.path.realpath(path)
    for why, name in (("whose files the run reads", "scenes"), ("whose files the run reads", "machines"),
                      ("whose files the run reads", "timing"), ("the tree's pages", "docs")):
        folder = os.path.join(repo, name)
        if inside(real, folder):
            return "%s '%s': is inside %s, %s" % (option, shown(path), shown(folder), why)
    code = os.path.join(repo, "experiments")
    rel = os.path.relpath(real, os.path.realpath(code))
    if inside(real, code) and not any(part.startswith("results") for part in rel.split(os.sep)):
        return "%s '%s': is inside %s, the code (a results folder there is named results*)" % (
            option, shown(path), shown(code))
    return None


def _own_place(path, results, is_page):
    """True for the places a results folder keeps for a page and its plots: a page (.md, not
    before-fit.md, a study's input) directly in it, and its img/ folder."""
    real, top = os.path.realpath(path), os.path.realpath(results)
    if is_page:
        name = os.path.basename(real)
        return os.path.dirname(real) == top and name.endswith(".md") and name != "before-fit.md"
    return real == os.path.join(top, "img")


def _kind_of_place(option, path, is_folder):
    """Why PATH cannot be the results folder or plots' folder (IS_FOLDER) or a page, whatever its
    place, or None: a control character in its name (the point lists hold one point a line), a
    name through /proc or /dev/fd (a stream, which a rename would replace), or an existing file
    of the other kind (a folder for a page; a file for a folder). The writes would refuse these
    too, but only after the runs."""
    what = "%s '%s'" % (option, shown(path))
    if any(ord(c) < 0x20 or ord(c) == 0x7f for c in path):
        return "%s: a control character in the name (a newline would split the point lists' lines)" % what
    if _through_stream(path):
        return "%s: is a stream or a file another process holds open (through /proc or /dev/fd)" % what
    try:
        st = os.stat(path)
    except OSError:
        return None
    if is_folder and not stat.S_ISDIR(st.st_mode):
        return "%s: is a file, not a folder" % what
    if not is_folder and not stat.S_ISREG(st.st_mode):
        return "%s: is a %s, not a regular file" % (what, "folder" if stat.S_ISDIR(st.st_mode) else "special file")
    return None


def _page_place(option, path, kept, images, inputs):
    """Why the page (or, with INPUTS None, the plots' folder) PATH may not be written, or None:
    inside a folder of KEPT ((what, folder, is-the-results-folder): the tree's and the results
    folder; a place the results folder keeps, _own_place, is allowed wherever that lies) or of
    IMAGES, the file of an input (INPUTS: identity -> (option, path)), or a hard link to a file
    of KEPT."""
    is_page = inputs is not None
    own = any(results and _own_place(path, folder, is_page) for _, folder, results in kept)
    for what, folder, results in kept + [(o, f, False) for o, f in (images if is_page else [])]:
        if inside(path, folder) and not own:
            where = "the folder %s" % shown(folder) if what is None else "the %s folder %s" % (what, shown(folder))
            return "%s '%s': is inside %s, whose files the run reads or writes" % (option, shown(path), where)
    if not is_page:
        return None
    try:
        st = os.stat(path)
    except OSError:
        return None
    key = (st.st_dev, st.st_ino) if stat.S_ISREG(st.st_mode) else None
    if key in inputs:
        what, input_path = inputs[key]
        what = "the file %s" % shown(input_path) if what == "argument" else "the %s file %s" % (
            what, shown(input_path))
        return "%s '%s': is %s, an input" % (option, shown(path), what)
    linked = linked_into(st, [(w, f) for w, f, _ in kept], os.path.realpath(path))
    if linked is not None:
        return "%s '%s': is a hard link to a file in %s, whose files the run reads or writes" % (
            option, shown(path), shown(linked[1]))
    return None


def check_places(prog, repo, argv):
    """`output_files.py --check-places PROG REPO [--results OPTION DIR] [--page OPTION FILE]...
    [--images OPTION DIR]... -- WORDS...`: the places a study script (sweep.sh, a study.sh) writes
    its results folder, pages and plots, checked before anything is made (exit 2, naming the
    option and the file; 0 when all are allowed):
    - the results folder: _results_place;
    - a page or a plots' folder: not in REPO's scenes/, machines/, timing/ and experiments/ (the
      code), nor in the results folder (whose files the run reads and writes) but for the places
      it keeps for them (_own_place), a page not in a plots' folder (a plot's name), not a file
      the command line WORDS names (named_files: a scene, an sshlogin file, a --config and its
      files), nor a hard link to a file of these folders."""
    split = argv.index("--") if "--" in argv else len(argv)
    words, opts = argv[split + 1:], argv[:split]
    given = {"--results": [], "--page": [], "--images": []}
    for i in range(0, len(opts) - 2, 3):
        given.setdefault(opts[i], []).append((opts[i + 1], opts[i + 2]))
    pages, images = given["--page"], given["--images"]
    results = given["--results"][-1] if given["--results"] else None
    kept = [(None, os.path.join(repo, name), False) for name in ("scenes", "machines", "timing", "experiments")]
    reason = None
    for option, path, is_folder in ([(o, p, True) for o, p in given["--results"] + images]
                                    + [(o, p, False) for o, p in pages]):
        reason = reason or _kind_of_place(option, path, is_folder)
    if reason is not None:
        import sys
        print("%s: %s" % (prog, reason), file=sys.stderr)
        return 2
    reason = _results_place(results[0], results[1], repo) if results else None
    advice = "give a results folder of your own"
    if reason is None:
        advice = "write pages and plots into docs/ or a folder of your own"
        if results:
            kept.append((results[0], results[1], True))
        inputs = {}
        for option, path in named_files(list(words)):
            if (option, path) not in pages:  # the page's own word on the command line
                inputs.setdefault(_identity(path), (option, path))
        for option, path in pages + images:
            reason = _page_place(option, path, kept, images, inputs if (option, path) in pages else None)
            if reason is not None:
                break
    if reason is None:
        return 0
    import sys
    print("%s: %s; %s" % (prog, reason, advice), file=sys.stderr)
    return 2
