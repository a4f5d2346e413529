#include "common/body_file.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "common/inertia_scale_check.hpp"
#include "common/warning.hpp"

namespace aloft::host {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw Error(source + ": " + what);
}

double number(const json& j, const std::string& key, const std::string& source) {
  if (!j.is_number()) fail(source, "\"" + key + "\" must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(source, "\"" + key + "\" must be finite");
  return v;
}

double positive(const json& parent, const std::string& key, const std::string& source) {
  if (!parent.contains(key)) fail(source, "missing \"" + key + "\"");
  const double v = number(parent.at(key), key, source);
  if (!(v > 0.0)) fail(source, "\"" + key + "\" must be positive");
  return v;
}

Eigen::Vector3d vector3(const json& j, const std::string& key, const std::string& source) {
  if (!j.is_array() || j.size() != 3) fail(source, "\"" + key + "\" must be an array of 3 numbers");
  return {number(j[0], key, source), number(j[1], key, source), number(j[2], key, source)};
}

Eigen::Quaterniond quaternion(const json& j, const std::string& key, const std::string& source) {
  if (!j.is_array() || j.size() != 4) {
    fail(source,
         "\"" + key +
             "\" must be a quaternion [w, x, y, z] (scalar first; scipy's as_quat() gives x, y, z, w)");
  }
  const Eigen::Quaterniond q(number(j[0], key, source), number(j[1], key, source), number(j[2], key, source),
                             number(j[3], key, source));
  if (!aloft::is_unit(q)) fail(source, "\"" + key + "\" is not a unit quaternion");
  return q.normalized();
}

void check(Status status, const std::string& source) {
  if (status != Status::ok) fail(source, std::string("inertia: ") + describe(status));
}

// Builds the tensor strictly, or with the measured slack and a one-line warning.
template <typename Make>
void make_measured(const Make& make, InertiaTensor<double>& out, const std::string& source) {
  Status s = make(InertiaTensor<double>::relative_tolerance());
  if (s == Status::tensor_breaks_triangle_inequality) {
    s = make(kMeasuredTriangleSlack);
    if (s == Status::ok) {
      const Eigen::Vector3d m = out.principal_moments();
      const double excess = m(2) - m(0) - m(1);
      char percent[32];
      std::snprintf(percent, sizeof percent, "%.1f", 100.0 * excess / m.sum());
      warn(source + ": principal moments break the triangle inequality by " + percent +
           " % of their sum (measured moments of a flat body?); simulating them as given");
    }
  }
  check(s, source);
}

// Every key the rotor's object may hold, both required: a rotor guessed is worse than an
// error, since its momentum sets the scale of every moment estimated with it.
BodyRotor parse_rotor(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "\"rotor\" must be an object {\"inertia_kg_m2\": J, \"axis\": [x, y, z]}");
  for (const auto& item : j.items()) {
    if (item.key() != "inertia_kg_m2" && item.key() != "axis") {
      fail(source, "unknown key \"rotor." + item.key() + "\" (a rotor has \"inertia_kg_m2\" and \"axis\")");
    }
  }
  if (!j.contains("inertia_kg_m2"))
    fail(source, "missing \"rotor.inertia_kg_m2\" (kg m^2, about its spin axis)");
  if (!j.contains("axis")) fail(source, "missing \"rotor.axis\" (its spin axis in body axes, [x, y, z])");
  BodyRotor rotor;
  rotor.inertia_kg_m2 = number(j["inertia_kg_m2"], "rotor.inertia_kg_m2", source);
  if (!(rotor.inertia_kg_m2 > 0.0)) fail(source, "\"rotor.inertia_kg_m2\" must be positive");
  const Eigen::Vector3d axis = vector3(j["axis"], "rotor.axis", source);
  // Any length is a direction (stableNorm: no overflow or underflow on the way); only
  // the zero vector has none.
  const double length = axis.stableNorm();
  if (!(length > 0.0) || !std::isfinite(length)) fail(source, "\"rotor.axis\" must be a direction, not zero");
  rotor.axis = axis / length;
  return rotor;
}

// The body's tensor is the whole assembly's, rotor included, so its moment about any
// axis through the centre of mass is at least the rotor's about its own parallel axis:
// a rotor at or above it is in another unit (g cm^2?) or belongs to another body.
void check_rotor_fits(const BodyRotor& rotor, const InertiaTensor<double>& inertia,
                      const std::string& source) {
  const double body_moment = rotor.axis.dot(inertia.tensor() * rotor.axis);
  if (rotor.inertia_kg_m2 < body_moment) return;
  char text[200];
  std::snprintf(text, sizeof text,
                "\"rotor.inertia_kg_m2\" (%.6g) is not below the whole body's moment about the rotor's axis "
                "(%.6g kg m^2), which includes the rotor",
                rotor.inertia_kg_m2, body_moment);
  fail(source, text);
}

InertiaTensor<double> parse_inertia(const json& body, double mass, bool has_mass, const std::string& source) {
  if (!body.contains("inertia") || !body["inertia"].is_object()) {
    fail(source, "missing \"inertia\" object");
  }
  const json& inertia = body["inertia"];
  const int forms =
      int(inertia.contains("tensor")) + int(inertia.contains("principal")) + int(inertia.contains("shape"));
  if (forms != 1) {
    fail(source, "\"inertia\" must hold exactly one of \"tensor\", \"principal\", \"shape\"");
  }
  InertiaTensor<double> out;
  if (inertia.contains("tensor")) {
    const json& t = inertia["tensor"];
    if (!t.is_array() || t.size() != 3) fail(source, "\"tensor\" must be a 3x3 array");
    if (t[0].is_number()) {
      fail(source,
           "\"tensor\" is the full 3x3 array [[Ixx, Ixy, Ixz], [Ixy, Iyy, Iyz], [Ixz, Iyz, Izz]]; "
           "for three principal moments write \"principal\": [I1, I2, I3]");
    }
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r) m.row(r) = vector3(t[size_t(r)], "tensor", source).transpose();
    make_measured([&](double slack) { return InertiaTensor<double>::make_from_tensor(m, out, slack); }, out,
                  source);
  } else if (inertia.contains("principal")) {
    const Eigen::Vector3d moments = vector3(inertia["principal"], "principal", source);
    const Eigen::Quaterniond axes = inertia.contains("axes") ? quaternion(inertia["axes"], "axes", source)
                                                             : Eigen::Quaterniond::Identity();
    make_measured(
        [&](double slack) { return InertiaTensor<double>::make_from_principal(moments, axes, out, slack); },
        out, source);
  } else {
    const json& shape = inertia["shape"];
    if (!has_mass) fail(source, "\"shape\" needs \"mass\"");
    if (!shape.is_object() || shape.size() != 1) {
      fail(source, "\"shape\" must be one of {\"cylinder\"}, {\"box\"}, {\"sphere\"}");
    }
    if (shape.contains("cylinder")) {
      const json& c = shape["cylinder"];
      check(InertiaTensor<double>::make_cylinder(mass, positive(c, "radius", source),
                                                 positive(c, "height", source), out),
            source);
    } else if (shape.contains("box")) {
      const json& b = shape["box"];
      check(InertiaTensor<double>::make_box(mass, positive(b, "x", source), positive(b, "y", source),
                                            positive(b, "z", source), out),
            source);
    } else if (shape.contains("sphere")) {
      check(InertiaTensor<double>::make_sphere(mass, positive(shape["sphere"], "radius", source), out),
            source);
    } else {
      fail(source, "unknown shape \"" + shape.begin().key() + "\" (cylinder, box or sphere)");
    }
  }
  return out;
}

// nlohmann's message without its internal "[json.exception.parse_error.101] " code.
std::string without_library_code(const std::string& message) {
  if (message.rfind("[json.exception.", 0) != 0) return message;
  const std::size_t end = message.find("] ");
  return end == std::string::npos ? message : message.substr(end + 2);
}

// SPEC §2's keys at each level; anything else is most likely a misspelling ("intertia",
// "marker"), which would otherwise be ignored without a word.
void warn_unknown_keys(const json& object, std::initializer_list<const char*> known, const std::string& where,
                       const std::string& source) {
  if (!object.is_object()) return;
  std::string unknown;
  for (const auto& item : object.items()) {
    bool found = false;
    for (const char* k : known) found = found || item.key() == k;
    if (!found) unknown += (unknown.empty() ? "\"" : ", \"") + where + item.key() + "\"";
  }
  if (!unknown.empty())
    warn(source + ": unknown key(s) " + unknown + " ignored (body file keys: docs/file-formats.md)");
}

void warn_unknown_body_keys(const json& j, const std::string& source) {
  warn_unknown_keys(j, {"name", "mass", "inertia", "markers", "imu", "rotor"}, "", source);
  if (j.contains("inertia")) {
    const json& inertia = j["inertia"];
    warn_unknown_keys(inertia, {"tensor", "principal", "axes", "shape"}, "inertia.", source);
    if (inertia.is_object() && inertia.contains("shape")) {
      const json& shape = inertia["shape"];
      if (shape.is_object() && shape.contains("cylinder")) {
        warn_unknown_keys(shape["cylinder"], {"radius", "height"}, "inertia.shape.cylinder.", source);
      }
      if (shape.is_object() && shape.contains("box")) {
        warn_unknown_keys(shape["box"], {"x", "y", "z"}, "inertia.shape.box.", source);
      }
      if (shape.is_object() && shape.contains("sphere")) {
        warn_unknown_keys(shape["sphere"], {"radius"}, "inertia.shape.sphere.", source);
      }
    }
  }
  if (j.contains("imu")) warn_unknown_keys(j["imu"], {"rotation", "position"}, "imu.", source);
}

Body parse_body(const json& j, const std::string& source) {
  if (!j.is_object()) fail(source, "a body file must be a JSON object");
  Body body;
  if (j.contains("name")) {
    if (!j["name"].is_string()) fail(source, "\"name\" must be a string");
    body.name = j["name"].get<std::string>();
  }
  const bool has_mass = j.contains("mass");
  if (has_mass) body.mass_kg = positive(j, "mass", source);
  body.inertia = parse_inertia(j, body.mass_kg, has_mass, source);
  if (j.contains("markers")) {
    if (!j["markers"].is_object()) fail(source, "\"markers\" must be an object of name: [x, y, z]");
    for (const auto& [name, position] : j["markers"].items()) {
      body.markers_m[name] = vector3(position, "markers." + name, source);
    }
  }
  if (j.contains("imu")) {
    const json& imu = j["imu"];
    if (!imu.is_object()) fail(source, "\"imu\" must be an object");
    if (imu.contains("rotation")) body.imu_to_body = quaternion(imu["rotation"], "imu.rotation", source);
    if (imu.contains("position")) body.imu_position_m = vector3(imu["position"], "imu.position", source);
  }
  if (j.contains("rotor")) {
    body.rotor = parse_rotor(j["rotor"], source);
    check_rotor_fits(*body.rotor, body.inertia, source);
  }
  warn_unknown_body_keys(j, source);
  if (const auto problem = inertia_scale_problem(body)) warn(source + ": " + *problem);
  return body;
}

}  // namespace

Body parse_body_json(const std::string& text, const std::string& source) {
  // Every exception of the JSON library (syntax, a number like 1e400 out of range, a
  // type mismatch) becomes aloft's one line naming the file, without the library's code.
  try {
    return parse_body(json::parse(text), source);
  } catch (const json::exception& e) {
    fail(source, "not a valid body file: " + without_library_code(e.what()));
  }
}

Body read_body_file(const std::string& path) {
  return with_file_context(path, [&] {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path + ": cannot open body file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_body_json(text.str(), path);
  });
}

Body read_body(const std::string& source, const std::string& json_text) {
  return json_text.empty() ? read_body_file(source) : parse_body_json(json_text, source);
}

}  // namespace aloft::host
