"""The GIF's palette (animate/palette.py): every colour when there are few, at most 256 otherwise with the
commonest kept exactly, each colour's nearest entry, and colours packed as 0xRRGGBB and back."""

import numpy as np

from rodparadox.animate.palette import GIF_COLOURS, nearest_entries, pack, palette_of, unpack


def test_the_palette_is_every_colour_when_there_are_few_and_stays_within_256():
    colours = np.array([0x000000, 0x00FF00, 0xFFFFFF], dtype=np.uint32)
    assert palette_of(colours, np.array([5, 1, 9])).tolist() == [[0, 0, 0], [0, 255, 0], [255, 255, 255]]
    many = np.arange(0, 2 ** 24, 4099, dtype=np.uint32)
    counts = np.ones(len(many), dtype=np.int64)
    counts[0] = 10 ** 6  # black covers most of the picture: it keeps its own entry, exactly
    palette = palette_of(many, counts)
    assert len(palette) == GIF_COLOURS == 256 and [0, 0, 0] in palette.tolist()


def test_a_colour_packs_to_0xRRGGBB_and_back():
    image = np.array([[[0x12, 0x34, 0x56], [255, 0, 1]]], dtype=np.uint8)
    assert pack(image).tolist() == [[0x123456, 0xFF0001]]
    assert unpack(pack(image).ravel()).tolist() == image[0].tolist()


def test_each_colour_maps_to_its_nearest_entry_the_first_of_equals():
    palette = np.array([[0, 0, 0], [100, 100, 100], [200, 200, 200], [100, 100, 100]], dtype=np.uint8)
    colours = pack(np.array([[[10, 0, 0], [120, 90, 100], [255, 255, 255], [150, 150, 150]]], dtype=np.uint8)).ravel()
    # (150, 150, 150) is as near 100 as 200: the first of equals, entry 1; entry 3 equals entry 1 and is never chosen
    assert nearest_entries(colours, palette).tolist() == [0, 1, 2, 1]
