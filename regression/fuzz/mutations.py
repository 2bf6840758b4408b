"""The mutations the fuzzer applies to a deck. Each takes the deck's root element and a
random.Random, changes the deck in place and returns a one-line description ("path: what"), or
None when the deck has nothing it applies to (the caller then draws another)."""

import copy
import os
import xml.etree.ElementTree as ElementTree

from decks import parameters, sublists

SPECIAL_NUMBERS = ["0", "-1", "1e308", "-1e308", "1e-308", "nan", "inf", "-inf", "0x10",
                   "1e309", "-0", "4.9e-324", "2147483648", ""]
SCALAR_TYPES = ("double", "int")
ARRAY_TYPES = ("Array(double)", "Array(int)")
GARBAGE_STRINGS = ["", " ", "xyz", "{}", "}{", "{1,,2}", "nan", "-1", "../", "*", "\u00e9\u00fc\u2603",
                   "a" * 5000, "x, y, z", "Steps/load", "\\", "%s%n", "1/0", "sqrt(-1)"]
TYPE_SWAPS = ["double", "int", "string", "bool", "Array(double)", "Array(int)", "Array(string)",
              "foo", ""]


def _pick(rng, items):
    return rng.choice(items) if items else None


def _entries(value):
    inner = value.strip().strip("{}").strip()
    return [entry.strip() for entry in inner.split(",")] if inner else []


def special_number(root, rng):
    parameter = _pick(rng, [p for p in parameters(root) if p.type in SCALAR_TYPES])
    if parameter is None:
        return None
    new = rng.choice(SPECIAL_NUMBERS)
    parameter.element.set("value", new)
    return "%s: %s -> %r" % (parameter.path, parameter.type, new)


def scaled_number(root, rng):
    """A plausible-looking but off value: the number times a power of ten, or its negative."""
    candidates = []
    for parameter in parameters(root):
        if parameter.type == "double":
            try:
                float(parameter.value)
                candidates.append(parameter)
            except ValueError:
                pass
    parameter = _pick(rng, candidates)
    if parameter is None:
        return None
    factor = rng.choice([1e-12, 1e-6, 1e-3, 1e3, 1e6, 1e12, -1.0])
    old = parameter.value
    new = repr(float(old) * factor)
    parameter.element.set("value", new)
    return "%s: %s times %g -> %s" % (parameter.path, old, factor, new)


def array_entry(root, rng):
    parameter = _pick(rng, [p for p in parameters(root)
                            if p.type in ARRAY_TYPES and _entries(p.value)])
    if parameter is None:
        return None
    entries = _entries(parameter.value)
    index = rng.randrange(len(entries))
    entries[index] = rng.choice(SPECIAL_NUMBERS)
    new = "{" + ", ".join(entries) + "}"
    parameter.element.set("value", new)
    return "%s: entry %d -> %s" % (parameter.path, index, new)


def array_shape(root, rng):
    parameter = _pick(rng, [p for p in parameters(root) if p.type.startswith("Array(")])
    if parameter is None:
        return None
    entries = _entries(parameter.value) or ["1"]
    choice = rng.randrange(6)
    if choice == 0:
        new, what = "{}", "empty"
    elif choice == 1:
        size = rng.choice([1000, 100000])
        new, what = "{" + ", ".join([entries[0]] * size) + "}", "%d entries" % size
    elif choice == 2:
        new, what = "{" + ", ".join(entries[:-1]) + "}", "one entry fewer"
    elif choice == 3:
        new, what = "{" + ", ".join(entries + [entries[-1]]) + "}", "one entry more"
    elif choice == 4:
        new, what = ", ".join(entries), "without braces"
    else:
        new, what = "{" + ", ".join(["nan"] * len(entries)) + "}", "all nan"
    parameter.element.set("value", new)
    return "%s: %s (%s)" % (parameter.path, what, new[:60])


def wrong_type(root, rng):
    parameter = _pick(rng, parameters(root))
    if parameter is None:
        return None
    if rng.random() < 0.5:
        old_type = parameter.type
        new_type = rng.choice([t for t in TYPE_SWAPS if t != old_type])
        parameter.element.set("type", new_type)
        return "%s: type %s -> %r (value %r)" % (parameter.path, old_type or "?", new_type,
                                                 parameter.value[:40])
    new = rng.choice(["2.5", "maybe", "true", "{1, 2}", "1e3", "twelve", "1,5"])
    parameter.element.set("value", new)
    return "%s: %s value -> %r" % (parameter.path, parameter.type, new)


def garbage_string(root, rng):
    parameter = _pick(rng, [p for p in parameters(root) if p.type in ("string", "Array(string)")])
    if parameter is None:
        return None
    new = rng.choice(GARBAGE_STRINGS)
    if parameter.type == "Array(string)" and rng.random() < 0.5:
        new = "{" + new + "}"
    parameter.element.set("value", new)
    return "%s: string -> %r" % (parameter.path, new[:40] + ("..." if len(new) > 40 else ""))


def delete_parameter(root, rng):
    parameter = _pick(rng, parameters(root))
    if parameter is None:
        return None
    parameter.parent.remove(parameter.element)
    return "%s: deleted" % parameter.path


def delete_sublist(root, rng):
    chosen = _pick(rng, sublists(root))
    if chosen is None:
        return None
    element, path, parent = chosen
    parent.remove(element)
    return "%s: list deleted" % path


def unknown_parameter(root, rng):
    lists = [(root, "")] + [(element, path) for element, path, _ in sublists(root)]
    element, path = rng.choice(lists)
    name = rng.choice(["Fuzz extra", "Tolerance", "Typo", "Module", "Type", "Time step"])
    if any(child.get("name") == name for child in element):
        name = name + " 2"
    ElementTree.SubElement(element, "Parameter", name=name, type="double", value="1")
    return "%s/%s: unknown parameter added" % (path, name)


def duplicate_sublist(root, rng):
    """A second copy of a list: two steps of one module, two materials, two loads."""
    candidates = sublists(root)
    steps = [c for c in candidates if c[1].startswith("Steps/") and c[1].count("/") == 1]
    chosen = _pick(rng, steps) if steps and rng.random() < 0.6 else _pick(rng, candidates)
    if chosen is None:
        return None
    element, path, parent = chosen
    twin = copy.deepcopy(element)
    same_name = rng.random() < 0.2
    if not same_name:
        twin.set("name", element.get("name", "") + " copy")
    parent.insert(list(parent).index(element) + 1, twin)
    return "%s: list duplicated%s" % (path, " under the same name" if same_name else "")


def duplicate_parameter(root, rng):
    parameter = _pick(rng, parameters(root))
    if parameter is None:
        return None
    twin = copy.deepcopy(parameter.element)
    parameter.parent.insert(list(parameter.parent).index(parameter.element) + 1, twin)
    return "%s: parameter given twice" % parameter.path


def bad_file(root, rng):
    parameter = _pick(rng, [p for p in parameters(root)
                            if p.type == "string" and os.path.isabs(p.value)])
    if parameter is None:
        return None
    new = rng.choice([os.path.dirname(parameter.value), parameter.value + ".missing", "/dev/null",
                      "/"])
    parameter.element.set("value", new)
    return "%s: file -> %s" % (parameter.path, new)


# (mutation, weight): files and arrays are where the known holes are, so they come up often.
MUTATIONS = [
    (special_number, 6), (scaled_number, 3), (array_entry, 5), (array_shape, 3),
    (wrong_type, 3), (garbage_string, 3), (delete_parameter, 3), (delete_sublist, 1),
    (unknown_parameter, 2), (duplicate_sublist, 3), (duplicate_parameter, 1), (bad_file, 2),
]


def mutate(root, rng, count):
    """Applies count mutations (drawing again where one does not apply); returns their
    descriptions."""
    functions = [function for function, _ in MUTATIONS]
    weights = [weight for _, weight in MUTATIONS]
    done = []
    for _ in range(50 * count):
        if len(done) == count:
            break
        function = rng.choices(functions, weights)[0]
        description = function(root, rng)
        if description is not None:
            done.append("%s: %s" % (function.__name__, description))
    return done
