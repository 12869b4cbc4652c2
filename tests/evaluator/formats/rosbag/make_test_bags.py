"""Writes the ROS1 bags the rosbag reader tests read back, with Debian's python3-rosbag: a writer
that shares no code with the C++ reader. Usage: /usr/bin/python3 make_test_bags.py OUT_DIR

Every value below is chosen so the expected results can be computed by hand (see the test).
"""
import math
import os
import sys

import genpy
import rosbag
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped, TransformStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage


class OldTfMessage(TFMessage):
    """ROS1 tf's tf/tfMessage (what older bags, e.g. the MIT Stata Center ones, record on /tf):
    the same definition and md5 sum as tf2_msgs/TFMessage under another type name."""
    _type = 'tf/tfMessage'


def stamp(seconds):
    return genpy.Time.from_sec(seconds)


def yaw_quaternion(message, yaw):
    message.x, message.y, message.z = 0.0, 0.0, math.sin(yaw / 2)
    message.w = math.cos(yaw / 2)


def scan(t, frame, ranges):
    message = LaserScan()
    message.header.stamp = stamp(t)
    message.header.frame_id = frame
    message.angle_min, message.angle_max, message.angle_increment = -1.5, 1.5, 0.75
    message.range_min, message.range_max = 0.1, 30.0
    message.ranges = ranges
    return message


def odometry(t, x, y, yaw, frame='odom', child='base_link'):
    message = Odometry()
    message.header.stamp = stamp(t)
    message.header.frame_id = frame
    message.child_frame_id = child
    message.pose.pose.position.x, message.pose.pose.position.y = x, y
    yaw_quaternion(message.pose.pose.orientation, yaw)
    return message


def transform(t, parent, child, x, y, yaw):
    message = TransformStamped()
    message.header.stamp = stamp(t)
    message.header.frame_id = parent
    message.child_frame_id = child
    message.transform.translation.x, message.transform.translation.y = x, y
    yaw_quaternion(message.transform.rotation, yaw)
    return message


def write(bag, topic, message, t):
    bag.write(topic, message, stamp(t))


def basic(path):
    """/scan (frame laser), /odom, /ground_truth, /tf_static base_link -> laser."""
    with rosbag.Bag(path, 'w') as bag:
        write(bag, '/tf_static', TFMessage([transform(0.0, 'base_link', 'laser', 0.2, 0.1, math.pi / 2)]), 99.0)
        for t, x, y, yaw in [(100.0, 0.0, 0.0, 0.0), (101.0, 1.0, 2.0, 0.5), (102.0, 2.0, 2.0, 1.0)]:
            write(bag, '/odom', odometry(t, x, y, yaw), t)
        for k in range(5):
            t = 100.0 + 0.5 * k
            write(bag, '/ground_truth', odometry(t, 0.5 * k, -0.5 * k, 0.0, frame='map'), t)
        ranges = [1.0, float('nan'), float('inf'), float('-inf'), 2.5]
        # Bag order differs from stamp order (101.25 is recorded before 100.5), 100.5 comes twice,
        # 99.5 and 102.5 lie outside the odometry's span [100, 102].
        for t, record in [(99.5, 99.5), (100.0, 100.0), (101.25, 100.4), (100.5, 100.6), (100.5, 100.7),
                          (102.0, 102.0), (102.5, 102.5)]:
            write(bag, '/scan', scan(t, 'laser', ranges), record)


def tf_odometry(path):
    """No Odometry topic: odom -> base_link and map -> odom on /tf (as tf/tfMessage), the laser
    mount base_link -> /base_laser published once on /tf."""
    with rosbag.Bag(path, 'w') as bag:
        write(bag, '/tf', OldTfMessage([transform(10.0, 'base_link', 'base_laser', 0.3, 0.0, math.pi)]), 10.0)
        for t, x, y, yaw in [(10.0, 0.0, 0.0, 0.0), (11.0, 1.0, 0.0, math.pi / 2), (12.0, 1.0, 1.0, math.pi / 2)]:
            write(bag, '/tf', OldTfMessage([transform(t, '/odom', '/base_link', x, y, yaw)]), t)
        for t in [10.0, 12.0]:
            write(bag, '/tf', OldTfMessage([transform(t, 'map', 'odom', 1.0, 0.0, math.pi / 2)]), t)
        for t in [10.5, 11.5]:
            write(bag, '/scan', scan(t, '/base_laser', [3.0] * 5), t)


def two_of_each(path):
    """Two LaserScan and two Odometry topics."""
    with rosbag.Bag(path, 'w') as bag:
        for t in [1.0, 2.0, 3.0]:
            write(bag, '/odom_a', odometry(t, t, 0.0, 0.0), t)
            write(bag, '/odom_b', odometry(t, 0.0, t, 0.0), t)
        for t in [1.5, 2.5]:
            write(bag, '/scan_front', scan(t, 'base_link', [1.0] * 5), t)
            write(bag, '/scan_rear', scan(t, 'base_link', [2.0] * 5), t)


def scans_only(path):
    with rosbag.Bag(path, 'w') as bag:
        write(bag, '/scan', scan(1.0, 'base_link', [1.0] * 5), 1.0)


def pose_references(path):
    """/scan and /odom, and a reference twice: as PoseStamped (/pose_gt) and PoseWithCovarianceStamped (/amcl)."""
    with rosbag.Bag(path, 'w') as bag:
        for t, x in [(1.0, 0.0), (2.0, 1.0), (3.0, 2.0)]:
            write(bag, '/odom', odometry(t, x, 0.0, 0.0), t)
        for t in [1.5, 2.5]:
            write(bag, '/scan', scan(t, 'base_link', [1.0] * 5), t)
        for t, x, y, yaw in [(1.0, 5.0, 1.0, 0.5), (3.0, 6.0, 2.0, 1.0)]:
            pose = PoseStamped()
            pose.header.stamp, pose.header.frame_id = stamp(t), 'map'
            pose.pose.position.x, pose.pose.position.y = x, y
            yaw_quaternion(pose.pose.orientation, yaw)
            write(bag, '/pose_gt', pose, t)
            amcl = PoseWithCovarianceStamped()
            amcl.header.stamp, amcl.header.frame_id = stamp(t), 'map'
            amcl.pose.pose.position.x, amcl.pose.pose.position.y = -x, -y
            yaw_quaternion(amcl.pose.pose.orientation, -yaw)
            write(bag, '/amcl', amcl, t)


def main():
    out = sys.argv[1]
    basic(os.path.join(out, 'basic.bag'))
    tf_odometry(os.path.join(out, 'tf_odometry.bag'))
    two_of_each(os.path.join(out, 'two_of_each.bag'))
    scans_only(os.path.join(out, 'scans_only.bag'))
    pose_references(os.path.join(out, 'pose_references.bag'))


if __name__ == '__main__':
    main()
