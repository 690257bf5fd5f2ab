"""pymavlink's mavwp as the reference reader and writer of QGC WPL 110 files, for WplInteropSpec.

    wpl_peer.py load FILE TYPE          mavwp loads FILE; prints one line per item
    wpl_peer.py save ITEMS FILE TYPE    mavwp saves the items listed in ITEMS to FILE

TYPE is mission, fence or rally (the mavwp class used). Printed lines and ITEMS lines share one
tab-separated layout, the WPL column order plus the mission type:
    seq current frame command p1 p2 p3 p4 x y z autocontinue mission_type
Floats are printed with repr(), the shortest text that reads back as the same Python float, so the
test sees exactly what mavwp holds in memory.
"""
import os
import sys

# Fence and rally items carry mission_type, a MAVLink 2 field; mavwp refuses them under MAVLink 1.
os.environ["MAVLINK20"] = "1"

from pymavlink import mavutil, mavwp  # noqa: E402

LOADERS = {
    "mission": mavwp.MAVWPLoader,
    "fence": mavwp.MissionItemProtocol_Fence,
    "rally": mavwp.MissionItemProtocol_Rally,
}


def load(path, kind):
    loader = LOADERS[kind]()
    loader.load(path)
    for i in range(loader.count()):
        w = loader.item(i)
        ints = [w.seq, w.current, w.frame, w.command]
        floats = [w.param1, w.param2, w.param3, w.param4, w.x, w.y, w.z]
        print("\t".join([str(v) for v in ints] + [repr(float(v)) for v in floats]
                        + [str(w.autocontinue), str(w.mission_type)]))


def save(items_path, path, kind):
    loader = LOADERS[kind]()
    with open(items_path) as f:
        for line in f:
            a = line.split("\t")
            loader.add(mavutil.mavlink.MAVLink_mission_item_message(
                0, 0, int(a[0]), int(a[2]), int(a[3]), int(a[1]), int(a[11]),
                float(a[4]), float(a[5]), float(a[6]), float(a[7]),
                float(a[8]), float(a[9]), float(a[10]), int(a[12])))
    loader.save(path)


if __name__ == "__main__":
    if sys.argv[1] == "load":
        load(sys.argv[2], sys.argv[3])
    else:
        save(sys.argv[2], sys.argv[3], sys.argv[4])
