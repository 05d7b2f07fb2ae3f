"""The command-line options vtu_shot.py (VTK) and paraview_shot.py (ParaView) share."""
import argparse


def shot_parser(description, subdivision_help):
    """An argparse parser for VTU PNG [--field] [--subdivision] [--centre] [--scale] [--size]."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("vtu")
    parser.add_argument("png")
    parser.add_argument("--field", default="homesh: certified minJ/maxJ",
                        help="cell or point field to colour by")
    parser.add_argument("--subdivision", type=int, default=3, help=subdivision_help)
    parser.add_argument("--centre", type=float, nargs=2, metavar=("X", "Y"))
    parser.add_argument("--scale", type=float, help="half the picture's height, model units")
    parser.add_argument("--size", type=int, nargs=2, default=(600, 600), metavar=("W", "H"))
    return parser
