// SplineLab's WebGL2 surface viewer (View3D): the public entry. The code lives in ./view3d/ by concept
// (camera, gl, overlay, input, geometry, math, shaders, constants; ./view3d/index.js assembles it); this file
// keeps the import path `lib/view3d.js` that demos, pages and course authors use.

import { View3D, linkViews, parseColor, computeNormals } from './view3d/index.js';

export { View3D, linkViews, parseColor, computeNormals };
export default View3D;
