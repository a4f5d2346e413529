#include "readers/osim_joint.hpp"

#include <pugixml.hpp>

#include <cmath>
#include <cstring>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/text_cells.hpp"

namespace aloft::host {

namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

bool is_joint_element(const pugi::xml_node& node) {
  return node.type() == pugi::node_element && ends_with(node.name(), "Joint") && node.attribute("name");
}

// N numbers from an element's text ("0 0 1"); throws when there are not exactly N.
std::vector<double> numbers(const pugi::xml_node& node, std::size_t count, const std::string& what,
                            const std::string& path) {
  std::vector<double> out;
  for (const std::string& cell : split_whitespace(node.child_value())) {
    double v = 0.0;
    if (!try_parse_number(cell, v) || !std::isfinite(v)) {
      throw Error(path + ": " + what + " holds '" + cell + "', not a finite number");
    }
    out.push_back(v);
  }
  if (out.size() != count) {
    throw Error(path + ": " + what + " needs " + std::to_string(count) + " numbers, has " +
                std::to_string(out.size()));
  }
  return out;
}

// [R, t] with R the body-fixed X-Y-Z angles of `orientation`; identity for absent elements.
Eigen::Isometry3d offset_frame(const pugi::xml_node& translation, const pugi::xml_node& orientation,
                               const std::string& what, const std::string& path) {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  if (translation) {
    const auto t = numbers(translation, 3, what + " translation", path);
    x.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  }
  if (orientation) {
    const auto a = numbers(orientation, 3, what + " orientation", path);
    x.linear() = (Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitX()) *
                  Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()))
                     .toRotationMatrix();
  }
  return x;
}

bool names_ground(std::string frame) {
  frame = trim(frame);
  while (!frame.empty() && frame.back() == '/') frame.pop_back();
  const std::size_t slash = frame.rfind('/');
  return (slash == std::string::npos ? frame : frame.substr(slash + 1)) == "ground";
}

// OpenSim 4: socket_parent_frame / socket_child_frame name a PhysicalOffsetFrame in the
// joint's <frames>, whose socket_parent is the body (or ground); or name a body directly.
void read_offsets_v4(const pugi::xml_node& joint, FreeJointColumns& out, const std::string& path) {
  auto offset_named = [&](const std::string& name) -> pugi::xml_node {
    for (const pugi::xml_node& f : joint.child("frames").children()) {
      if (name == f.attribute("name").value()) return f;
    }
    return {};
  };
  const std::string parent = trim(joint.child_value("socket_parent_frame"));
  const pugi::xml_node parent_frame = offset_named(parent);
  const std::string parent_base = parent_frame ? parent_frame.child_value("socket_parent") : parent;
  if (!names_ground(parent_base)) {
    throw Error(path + ": joint " + joint.attribute("name").value() + " connects to '" + parent_base +
                "', not ground: its coordinates give a pose relative to that body, not a free flight");
  }
  if (parent_frame) {
    out.parent_offset = offset_frame(parent_frame.child("translation"), parent_frame.child("orientation"),
                                     "parent frame " + parent, path);
  }
  const std::string child = trim(joint.child_value("socket_child_frame"));
  if (const pugi::xml_node child_frame = offset_named(child)) {
    out.child_offset = offset_frame(child_frame.child("translation"), child_frame.child("orientation"),
                                    "child frame " + child, path);
  }
}

// OpenSim 3: <parent_body>, <location_in_parent>, <orientation_in_parent>, <location>,
// <orientation> inside the joint.
void read_offsets_v3(const pugi::xml_node& joint, FreeJointColumns& out, const std::string& path) {
  const std::string parent = trim(joint.child_value("parent_body"));
  if (!names_ground(parent)) {
    throw Error(path + ": joint " + joint.attribute("name").value() + " connects to '" + parent +
                "', not ground: its coordinates give a pose relative to that body, not a free flight");
  }
  out.parent_offset = offset_frame(joint.child("location_in_parent"), joint.child("orientation_in_parent"),
                                   "location/orientation_in_parent", path);
  out.child_offset =
      offset_frame(joint.child("location"), joint.child("orientation"), "location/orientation", path);
}

// The function element of a TransformAxis (OpenSim 4: a child named "function"
// by attribute; OpenSim 3: wrapped in <function>), or an empty node.
pugi::xml_node axis_function(const pugi::xml_node& transform_axis) {
  for (const pugi::xml_node& child : transform_axis.children()) {
    if (child.type() != pugi::node_element) continue;
    const std::string name = child.name();
    if (name == "function")
      return child.first_child().type() == pugi::node_element ? child.first_child() : pugi::xml_node();
    if (name != "coordinates" && name != "axis") return child;
  }
  return {};
}

JointAxis transform_axis(const pugi::xml_node& spatial, const char* which, const std::string& joint_name,
                         const std::string& path) {
  pugi::xml_node node;
  for (const pugi::xml_node& a : spatial.children("TransformAxis")) {
    if (std::strcmp(a.attribute("name").value(), which) == 0) node = a;
  }
  const std::string what = "joint " + joint_name + " " + which;
  if (!node) throw Error(path + ": " + what + " is missing from its SpatialTransform");
  JointAxis out;
  const auto axis = numbers(node.child("axis"), 3, what + " axis", path);
  const Eigen::Vector3d v(axis[0], axis[1], axis[2]);
  if (!(v.norm() > 1e-12)) throw Error(path + ": " + what + " has a zero axis");
  out.axis = v.normalized();
  const std::vector<std::string> coordinates = split_whitespace(node.child_value("coordinates"));
  if (coordinates.size() > 1) throw Error(path + ": " + what + " follows several coordinates");
  const pugi::xml_node function = axis_function(node);
  const std::string kind = function ? function.name() : "";
  if (kind == "Constant") {
    out.offset = numbers(function.child("value"), 1, what + " Constant value", path)[0];
  } else if (coordinates.empty()) {
    if (!kind.empty() && kind != "LinearFunction") {
      throw Error(path + ": " + what + " uses a " + kind + " without a coordinate");
    }
    out.offset = 0.0;  // no coordinate: fixed at zero
  } else if (kind.empty() || kind == "LinearFunction") {
    out.coordinate = coordinates.front();
    if (!kind.empty()) {
      const auto c = numbers(function.child("coefficients"), 2, what + " LinearFunction coefficients", path);
      out.scale = c[0];
      out.offset = c[1];
    }
  } else {
    throw Error(path + ": " + what + " maps its coordinate through a " + kind +
                "; only LinearFunction and Constant are read");
  }
  return out;
}

FreeJointColumns custom_joint(const pugi::xml_node& joint, const std::string& name, const std::string& path) {
  const pugi::xml_node spatial = joint.child("SpatialTransform");
  if (!spatial) throw Error(path + ": CustomJoint " + name + " has no SpatialTransform");
  FreeJointColumns out;
  const char* rotations[3] = {"rotation1", "rotation2", "rotation3"};
  const char* translations[3] = {"translation1", "translation2", "translation3"};
  for (std::size_t i = 0; i < 3; ++i) out.rotations[i] = transform_axis(spatial, rotations[i], name, path);
  for (const char* t : translations) out.translations.push_back(transform_axis(spatial, t, name, path));
  return out;
}

FreeJointColumns free_joint(const pugi::xml_node& joint, const std::string& name, const std::string& path) {
  std::vector<std::string> coordinates;
  for (const pugi::xpath_node& c : joint.select_nodes(".//Coordinate")) {
    coordinates.push_back(c.node().attribute("name").value());
  }
  if (coordinates.size() != 6) {
    throw Error(path + ": FreeJoint " + name + " lists " + std::to_string(coordinates.size()) +
                " coordinates, not 6");
  }
  FreeJointColumns out;
  const Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                   Eigen::Vector3d::UnitZ()};
  for (std::size_t i = 0; i < 3; ++i) out.rotations[i] = JointAxis{axes[i], coordinates[i], 1.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i)
    out.translations.push_back(JointAxis{axes[i], coordinates[3 + i], 1.0, 0.0});
  return out;
}

}  // namespace

static FreeJointColumns read_osim_joint_unguarded(const std::string& osim_path,
                                                  const std::string& joint_name) {
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_file(osim_path.c_str());
  if (!parsed) {
    throw Error(osim_path + ": not a readable OpenSim model (" + parsed.description() + " at byte " +
                std::to_string(parsed.offset) + ")");
  }
  const pugi::xml_node joint = doc.find_node([&](const pugi::xml_node& n) {
    return is_joint_element(n) && joint_name == n.attribute("name").value();
  });
  if (!joint) {
    std::string names;
    std::size_t found = 0;
    doc.find_node([&](const pugi::xml_node& n) {
      if (is_joint_element(n) && found++ < 20)
        names += (names.empty() ? "" : ", ") + std::string(n.attribute("name").value());
      return false;
    });
    throw Error(osim_path + ": no joint named '" + joint_name +
                "' (joints: " + (names.empty() ? "none" : names) + ")");
  }
  const std::string type = joint.name();
  FreeJointColumns out;
  if (type == "FreeJoint") {
    out = free_joint(joint, joint_name, osim_path);
  } else if (type == "CustomJoint") {
    out = custom_joint(joint, joint_name, osim_path);
  } else {
    throw Error(osim_path + ": joint " + joint_name + " is a " + type +
                "; a free body needs a FreeJoint or a CustomJoint");
  }
  if (joint.child("parent_body")) {
    read_offsets_v3(joint, out, osim_path);
  } else {
    read_offsets_v4(joint, out, osim_path);
  }
  out.source = type + " " + joint_name + " of " + osim_path;
  return out;
}

FreeJointColumns read_osim_joint(const std::string& osim_path, const std::string& joint_name) {
  return with_file_context(osim_path, [&] { return read_osim_joint_unguarded(osim_path, joint_name); });
}

}  // namespace aloft::host
