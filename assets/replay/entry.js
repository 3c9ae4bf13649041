// The parts of three.js that the replay page (src/replay/page/) uses,
// bundled by build.sh into one classic script that defines the global
// `PegdynThree`.
//
// Why a bundle: the page must open from disk with no network and no second
// file. three.js ships as ES modules (three.module.js imports
// ./three.core.js, OrbitControls imports the bare name "three"); an inline
// module cannot import another inline module by name, so the alternatives
// are an import map whose entries are data:/blob: URLs of the module texts
// (rewriting three.module.js's relative import at load time) or a bundle
// made once. A bundle is one plain script, loads in any browser that runs
// the code at all, is tree-shaken to what the page uses (about a third of
// three.js) and is rebuilt byte for byte from the versions pinned in
// package-lock.json.
export {
  ArrowHelper,
  AxesHelper,
  BufferAttribute,
  BufferGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  DirectionalLight,
  DoubleSide,
  Group,
  HemisphereLight,
  Line,
  LineBasicMaterial,
  LineLoop,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PerspectiveCamera,
  Quaternion,
  REVISION,
  Scene,
  ShapeUtils,
  SphereGeometry,
  Vector2,
  Vector3,
  WebGLRenderer,
} from "three";
export { OrbitControls } from "three/addons/controls/OrbitControls.js";
