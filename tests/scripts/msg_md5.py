#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Prints {"md5": ..., "definition": ...} of a ROS 1 message file as genmsg (Debian's python3-genmsg)
computes them: what roscpp and mqtt_client announce for the type.

Usage: msg_md5.py PACKAGE/TYPE MSG_DIR   (std_msgs from /usr/share/std_msgs/msg)
"""
import json
import sys

import genmsg
import genmsg.gentools
import genmsg.msg_loader

full_type, msg_dir = sys.argv[1], sys.argv[2]
package = full_type.split("/")[0]
context = genmsg.MsgContext.create_default()
search = {"std_msgs": ["/usr/share/std_msgs/msg"], package: [msg_dir]}
spec = genmsg.msg_loader.load_msg_by_type(context, full_type, search)
genmsg.msg_loader.load_depends(context, spec, search)
json.dump({"md5": genmsg.gentools.compute_md5(context, spec),
           "definition": genmsg.gentools.compute_full_text(context, spec)}, sys.stdout)
