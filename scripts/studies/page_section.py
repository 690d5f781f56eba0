"""Replace the text between two marker lines of a docs page (the generated
sections of docs/results/*.md); exit naming the page if it lacks them."""
import sys


def write_section(page, begin, end, lines):
    before, found_begin, rest = open(page).read().partition(begin)
    _, found_end, after = rest.partition(end)
    if not (found_begin and found_end):
        sys.exit(f"{page}: no markers ({begin} ... {end})")
    open(page, "w").write(before + "\n".join([begin] + lines + [end]) + after)
