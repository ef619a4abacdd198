import sys
sys.exit(3)  # stands for a python3 without matplotlib (tests/test_topography_cli.cpp)
