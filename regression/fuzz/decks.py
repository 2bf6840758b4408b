"""The shipped decks the fuzzer mutates, made cheap enough to run hundreds of times.

A deck is a Teuchos ParameterList in XML. Each base deck is read with ElementTree, its relative
file paths are made absolute (the mutated copies live elsewhere), and a few parameters that only
set how long it runs are scaled down: box meshes to at most a few hundred elements, explicit end
times to a tenth, contact tables to a coarser resolution. The reduced deck must still run clean
(the harness checks it before mutating it).
"""

import copy
import math
import os
import xml.etree.ElementTree as ElementTree

# Shipped decks, relative to the source root. The wheel-modes scene and the modal ring are left
# out: they run for minutes and for 5-20 s whatever is scaled down.
BASE_DECKS = [
    "inputs/demo.xml",
    "inputs/scenes/contact_patch.xml",
    "inputs/scenes/wheelset_on_track.xml",
] + [
    "inputs/verification/%s/deck.xml" % case
    for case in [
        "cantilever_timoshenko",
        "contact_patch_hertz",
        "explicit_bar_wave",
        "explicit_cantilever",
        "explicit_rayleigh_wave",
        "explicit_rigid_body",
        "explicit_rigid_rotation",
        "explicit_spring_mass",
        "explicit_sprung_block",
        "gravity_column",
        "modal_cantilever",
        "modal_free_block",
        "patch_test",
        "tied_bar",
        "wheelset_cone_on_crown",
        "wheelset_s1002_60e1",
    ]
]

# Upper bound on the elements of a generated box after reduction; the demo keeps its mesh (its
# loaded side set selects no whole face on a coarser one).
MAX_BOX_ELEMENTS = 400
MAX_BOX_ELEMENTS_OF = {"inputs/demo.xml": 20000}


class Parameter:
    """One <Parameter> of a deck with its slash-separated path below the root list."""

    def __init__(self, element, path, parent):
        self.element = element
        self.path = path
        self.parent = parent

    @property
    def type(self):
        return self.element.get("type", "")

    @property
    def value(self):
        return self.element.get("value", "")


def parameters(root):
    """Every <Parameter> of the deck, depth first, with its path and parent list."""
    found = []

    def walk(element, prefix):
        for child in element:
            name = child.get("name", "")
            path = prefix + "/" + name if prefix else name
            if child.tag == "Parameter":
                found.append(Parameter(child, path, element))
            elif child.tag == "ParameterList":
                walk(child, path)

    walk(root, "")
    return found


def sublists(root):
    """Every <ParameterList> below the root as (element, path, parent)."""
    found = []

    def walk(element, prefix):
        for child in element:
            if child.tag != "ParameterList":
                continue
            path = prefix + "/" + child.get("name", "") if prefix else child.get("name", "")
            found.append((child, path, element))
            walk(child, path)

    walk(root, "")
    return found


def _make_paths_absolute(root, deck_dir):
    """Points every string parameter naming an existing file at its absolute path."""
    for parameter in parameters(root):
        if parameter.type != "string" or not parameter.value:
            continue
        candidate = os.path.normpath(os.path.join(deck_dir, parameter.value))
        if os.path.isfile(candidate):
            parameter.element.set("value", candidate)


def _reduce_box(parameter, limit):
    """Divides a box's element counts by one power of two until the box is small."""
    counts = [int(text) for text in parameter.value.strip("{} ").split(",")]
    divisor = 1
    while math.prod(max(1, n // divisor) for n in counts) > limit:
        divisor *= 2
    if divisor > 1:
        reduced = [max(1, n // divisor) for n in counts]
        parameter.element.set("value", "{" + ", ".join(str(n) for n in reduced) + "}")


def _reduce(root, box_limit):
    """Scales down what only decides the run time (see the module comment)."""
    for parameter in parameters(root):
        name = parameter.path.rsplit("/", 1)[-1]
        if name == "Elements" and parameter.path.startswith("Mesh/Box"):
            _reduce_box(parameter, box_limit)
        elif name == "End time":
            parameter.element.set("value", repr(float(parameter.value) / 10))
        elif name == "Table resolution":
            parameter.element.set("value", repr(max(float(parameter.value), 2e-4)))


class BaseDeck:
    """A shipped deck, its file paths absolute and its run time reduced."""

    def __init__(self, source_root, relative_path):
        self.name = relative_path
        path = os.path.join(source_root, relative_path)
        self.root = ElementTree.parse(path).getroot()
        _make_paths_absolute(self.root, os.path.dirname(path))
        _reduce(self.root, MAX_BOX_ELEMENTS_OF.get(relative_path, MAX_BOX_ELEMENTS))

    def copy(self):
        return copy.deepcopy(self.root)


def load_base_decks(source_root):
    return [BaseDeck(source_root, name) for name in BASE_DECKS]


def write_deck(root, path, header_lines):
    """Writes a (mutated) deck with a comment saying how it was made."""
    body = ElementTree.tostring(root, encoding="unicode")
    comment = "\n".join("  " + line.replace("--", "- -") for line in header_lines)
    with open(path, "w", encoding="utf-8") as deck:
        deck.write("<!--\n" + comment + "\n-->\n" + body + "\n")


NUMERIC_TYPES = ("double", "int", "Array(double)", "Array(int)")


def _refusable(entry):
    """A number railfe must refuse: NaN, infinite (1e309 included) or hexadecimal."""
    text = entry.strip().lower().lstrip("+-")
    if text.startswith("0x"):
        return True
    try:
        return not math.isfinite(float(text))
    except ValueError:
        return False


def refusable_numbers(root):
    """(path, value) of every numeric parameter of the deck holding a NaN, an infinity or a
    hexadecimal number, alone or inside an array."""
    found = []
    for parameter in parameters(root):
        if parameter.type not in NUMERIC_TYPES:
            continue
        entries = parameter.value.strip().strip("{}").split(",")
        if any(_refusable(entry) for entry in entries):
            found.append((parameter.path, parameter.value[:60]))
    return found
