// Camera matrices (see camera_matrices.h). Projections follow glTF 2.0 section 3.10 but map
// depth to [0, 1] instead of [-1, 1].
#include "context/camera_matrices.h"

#include <cmath>

namespace ontile {
namespace {

glm::dmat4 perspective_zo(double yfov, double aspect, double znear, double zfar) {
  const double f = 1.0 / std::tan(yfov * 0.5);
  glm::dmat4 m(0.0);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][3] = -1.0;
  if (zfar > 0.0) {
    m[2][2] = zfar / (znear - zfar);
    m[3][2] = znear * zfar / (znear - zfar);
  } else {  // infinite far plane: the limit of the above as zfar -> infinity
    m[2][2] = -1.0;
    m[3][2] = -znear;
  }
  return m;
}

glm::dmat4 orthographic_zo(double xmag, double ymag, double znear, double zfar) {
  glm::dmat4 m(1.0);
  m[0][0] = 1.0 / xmag;
  m[1][1] = 1.0 / ymag;
  m[2][2] = 1.0 / (znear - zfar);
  m[3][2] = znear / (znear - zfar);
  return m;
}

// The same projections with depth reversed: window depth near (far - d) / ((far - near) d) for
// perspective (near / d with an infinite far plane) and (far - d) / (far - near) for
// orthographic, at view distance d.
glm::dmat4 perspective_reversed_zo(double yfov, double aspect, double znear, double zfar) {
  glm::dmat4 m = perspective_zo(yfov, aspect, znear, zfar);
  if (zfar > 0.0) {
    m[2][2] = znear / (zfar - znear);
    m[3][2] = znear * zfar / (zfar - znear);
  } else {  // infinite far plane: the limit as zfar -> infinity
    m[2][2] = 0.0;
    m[3][2] = znear;
  }
  return m;
}

glm::dmat4 orthographic_reversed_zo(double xmag, double ymag, double znear, double zfar) {
  glm::dmat4 m = orthographic_zo(xmag, ymag, znear, zfar);
  m[2][2] = 1.0 / (zfar - znear);
  m[3][2] = zfar / (zfar - znear);
  return m;
}

}  // namespace

CameraMatrices camera_matrices(const Camera& camera, double aspect_ratio, bool reversed_z) {
  CameraMatrices m;
  const glm::dmat4& world = camera.world;
  m.view = glm::inverse(world);
  m.position = glm::dvec3(world[3]);
  if (camera.type == Camera::Type::Perspective) {
    m.projection = (reversed_z ? perspective_reversed_zo : perspective_zo)(
        camera.yfov_rad, aspect_ratio, camera.znear, camera.zfar);
  } else {
    // Keep ymag and derive xmag from the target's aspect ratio, as for perspective cameras.
    m.projection = (reversed_z ? orthographic_reversed_zo : orthographic_zo)(
        camera.ymag * aspect_ratio, camera.ymag, camera.znear,
        camera.zfar > camera.znear ? camera.zfar : camera.znear + 1e4);
  }
  m.view_projection = m.projection * m.view;
  return m;
}

}  // namespace ontile
