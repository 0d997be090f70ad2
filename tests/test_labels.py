"""Letters of points: coincident points written together, no two letters overlapping."""

from shapely.geometry import LineString

from graphplan.drawing import LabelRequest, merge_coincident, place_labels, text_box


def test_coincident_points_are_written_together():
    reqs = [LabelRequest((10, 10), "p", group="v"), LabelRequest((10.5, 10), "b", group="v"),
            LabelRequest((10.2, 10), "b", group="v"), LabelRequest((10, 10), "π", group="a"),
            LabelRequest((30, 10), "a", group="v")]
    out = merge_coincident(reqs, 1.0)
    # "b" twice is written once; another group's point is not merged
    assert [r.text for r in out] == ["p, b", "π", "a"]


def test_crowded_letters_do_not_overlap_and_avoid_lines():
    # twelve points 3 mm apart on a line: every letter must find its own spot
    reqs = [LabelRequest((50 + 3 * i, 50), f"s{i}") for i in range(12)]
    line = LineString([(40, 50), (100, 50)])
    texts = place_labels(reqs, [line], layer="text", id_prefix="t")
    boxes = [text_box(t) for t in texts]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            assert boxes[i].intersection(boxes[j]).area < 1e-9
    assert sum(b.intersects(line) for b in boxes) == 0
    assert len({t.id for t in texts}) == 12


def test_keep_out_is_respected():
    from shapely.geometry import box

    wall = box(0, 0, 100, 48)  # everything above y = 48 is taken
    texts = place_labels([LabelRequest((50, 50), "A", 5.0)], [], layer="text", id_prefix="k",
                         keep_out=[wall])
    assert not text_box(texts[0]).intersects(wall)


def test_the_batched_boxes_are_the_boxes_of_the_texts():
    """The placer judges a ring's spots in batches (shapely's vectorised predicates); each
    spot's box must be exactly ``text_box(text_at_centre(c)).buffer(0.3)`` — vertex for
    vertex, no tolerance — so that it makes the same choices as one spot at a time."""
    import random

    import numpy as np
    import shapely

    from graphplan.drawing.items import text_at_centre
    from graphplan.drawing.labels import _label_boxes

    rng = random.Random(7)
    for _ in range(500):
        r = LabelRequest((0.0, 0.0), rng.choice(["A", "p, b", "S2", "Pи3", "(12)", "Ё"]),
                         rng.choice([2.5, 3.5, 5.0]))
        cs = [np.array([rng.uniform(-50, 850), rng.uniform(-50, 600)]) for _ in range(3)]
        for c, got in zip(cs, _label_boxes(cs, r), strict=True):
            want = text_box(text_at_centre((float(c[0]), float(c[1])), r.text, r.height,
                                           layer="text")).buffer(0.3)
            assert shapely.equals_exact(got, want, tolerance=0.0)
