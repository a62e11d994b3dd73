#!/usr/bin/env python3
"""A flame graph from `perf script` output, with no other tool (Debian has none packaged).

    perf record --call-graph dwarf -F 500 -o perf.data build/bin/rt scenes/twocubes4 -n
    perf script -i perf.data | scripts/perf-flamegraph.py "title" > profile.svg

Each sample's stack is folded root first into one line; the SVG draws every frame as a box as
wide as its share of the samples, callers below callees (Brendan Gregg's layout). Frames are
shortened to their function's name (no arguments, no namespaces of the standard library).
"""
import html
import re
import sys
import zlib
from collections import defaultdict


def short(symbol):
    symbol = re.sub(r"\+0x[0-9a-f]+$", "", symbol)  # the offset into the function
    symbol = symbol.replace("(anonymous namespace)::", "")
    symbol = re.sub(r"\(.*", "", symbol)  # arguments and clone suffixes
    symbol = re.sub(r"<.*>", "<>", symbol)  # template arguments
    return symbol


def fold(lines):
    stacks = defaultdict(int)
    frames = []
    for line in lines:
        line = line.rstrip("\n")
        if not line.strip():
            if frames:
                stacks[";".join(reversed(frames))] += 1
            frames = []
        elif line.startswith((" ", "\t")):
            parts = line.strip().split(" ", 1)
            if len(parts) == 2:
                symbol = re.sub(r" \(.*\)$", "", parts[1])  # the object's path
                if symbol != "[unknown]":
                    frames.append(short(symbol))
    if frames:
        stacks[";".join(reversed(frames))] += 1
    return stacks


def tree(stacks):
    root = {"n": 0, "kids": {}}
    for stack, count in stacks.items():
        node = root
        node["n"] += count
        for frame in stack.split(";"):
            node = node["kids"].setdefault(frame, {"n": 0, "kids": {}})
            node["n"] += count
    return root


def svg(root, title, width=1200, row=16):
    boxes = []
    depth_max = [0]

    def place(node, name, x, depth):
        w = node["n"] / root["n"] * width
        if w < 0.5:
            return
        depth_max[0] = max(depth_max[0], depth)
        boxes.append((x, depth, w, name, node["n"]))
        for kid_name, kid in sorted(node["kids"].items()):
            place(kid, kid_name, x, depth + 1)
            x += kid["n"] / root["n"] * width

    place(root, "all", 0.0, 0)
    height = (depth_max[0] + 3) * row
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
        f'font-family="monospace" font-size="11">',
        f'<text x="4" y="{row - 3}">{html.escape(title)} ({root["n"]} samples)</text>',
    ]
    for x, depth, w, name, n in boxes:
        y = height - (depth + 1) * row
        share = 100.0 * n / root["n"]
        hue = 10 + zlib.crc32(name.encode()) % 40  # stable from run to run
        label = html.escape(name)
        out.append(
            f'<g><title>{label} {share:.1f}%</title>'
            f'<rect x="{x:.1f}" y="{y}" width="{w:.1f}" height="{row - 1}" '
            f'fill="hsl({hue},85%,60%)"/>'
        )
        chars = int(w / 7)
        if chars > 3:
            text = label if len(name) <= chars else html.escape(name[: chars - 2]) + ".."
            out.append(f'<text x="{x + 2:.1f}" y="{y + row - 4}">{text}</text>')
        out.append("</g>")
    out.append("</svg>")
    return "\n".join(out)


if __name__ == "__main__":
    print(svg(tree(fold(sys.stdin)), sys.argv[1] if len(sys.argv) > 1 else "profile"))
