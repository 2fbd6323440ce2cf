// View3D's WebGL2 side: programs, buffers of meshes / segments / points, colour-map textures and the render pass.

import { colormapLUT } from '../colormap.js';
import { FLAT_FS, LINE_VS, MESH_FS, MESH_VS, POINT_FS, POINT_VS } from './shaders.js';

/** Are two typed arrays equal element by element? */
function sameArray(a, b) {
  if (a === b) return true;
  if (!a || !b || a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

/** @typedef {import('./index.js').Viewer} Viewer */
/** WebGL2 methods of View3D. Installed on View3D.prototype by ./index.js. */
export class GlPart {
  /** @this {Viewer} */
  _initGL() {
    const gl = this.gl;
    // Compile and link without waiting: no status query here (each one is a synchronous round trip to the GPU
    // process that waits for the compiler), so the driver compiles while the demo builds the rest of its page; with
    // KHR_parallel_shader_compile it compiles on its own threads. _readyPrograms() reads the status at the first draw.
    gl.getExtension('KHR_parallel_shader_compile');
    const compile = (type, src) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      return s;
    };
    const program = (vs, fs, uniforms) => {
      const p = gl.createProgram();
      const shaders = [compile(gl.VERTEX_SHADER, vs), compile(gl.FRAGMENT_SHADER, fs)];
      for (const s of shaders) gl.attachShader(p, s);
      gl.linkProgram(p);
      return { p, shaders, uniforms, u: null };
    };
    this.prog = {
      mesh: program(MESH_VS, MESH_FS, ['uView', 'uProj', 'uRange', 'uColor', 'uOpacity', 'uUseMap', 'uMap']),
      line: program(LINE_VS, FLAT_FS, ['uView', 'uProj', 'uViewport', 'uWidth', 'uBias', 'uColor']),
      point: program(POINT_VS, POINT_FS, ['uView', 'uProj', 'uSize', 'uHighlight']),
    };
    this._progReady = false;
    gl.flush(); // (hands the compiles to the GPU process now, not at the first draw's first synchronous call)
    this.cornerBuf = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cornerBuf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([0, -1, 1, -1, 1, 1, 0, -1, 1, 1, 0, 1]), gl.STATIC_DRAW);
    this.maps = {};
    for (const obj of this.objects.values()) { obj.gpu = null; obj._reuse = null; }
  }

  /** The programs' link status and uniform locations (and the largest point size), read once before the first
   * draw; throws (like a failed compile did in _initGL before) with the compiler's or linker's log. */
  /** @this {Viewer} */
  _readyPrograms() {
    if (this._progReady) return;
    const gl = this.gl;
    for (const pr of Object.values(this.prog)) {
      if (!gl.getProgramParameter(pr.p, gl.LINK_STATUS) && !gl.isContextLost()) {
        const bad = pr.shaders.find((s) => !gl.getShaderParameter(s, gl.COMPILE_STATUS));
        throw new Error(bad ? 'shader: ' + gl.getShaderInfoLog(bad) : 'program: ' + gl.getProgramInfoLog(pr.p));
      }
      pr.u = {};
      for (const name of pr.uniforms) pr.u[name] = gl.getUniformLocation(pr.p, name);
    }
    // (a synchronous query too: it waits for the commands before it, the compiles included)
    const range = gl.getParameter(gl.ALIASED_POINT_SIZE_RANGE);
    this.maxPointSize = range ? range[1] : 64;
    this._progReady = true;
  }

  /** @this {Viewer} */
  _mapTexture(name) {
    const gl = this.gl;
    if (this.maps[name]) return this.maps[name];
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 256, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, colormapLUT(name, 256));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    return (this.maps[name] = tex);
  }

  // Buffers and vertex arrays are reused when an object is replaced by one of the same kind (a surface redrawn
  // while a point is dragged): `pool` holds the previous upload's VAOs and buffers, taken in the same order and
  // rewritten in place (bufferSubData when the size is unchanged); whatever is left over is deleted. Index
  // buffers stay index buffers (WebGL fixes a buffer's target at its first bind).
  /** @this {Viewer} */
  _pool(old) {
    if (!old) return { main: null, parts: [], bufs: [], ibufs: [], indices: null };
    return { main: old.vao || null, parts: old.parts.slice().reverse(), bufs: (old.buffers || []).slice().reverse(), ibufs: old.ibuf ? [old.ibuf] : [], indices: old.indices || null };
  }

  /** @this {Viewer} */
  _buffer(pool, data, target) {
    const gl = this.gl;
    const index = target === gl.ELEMENT_ARRAY_BUFFER;
    const b = (index ? pool.ibufs.pop() : pool.bufs.pop()) || gl.createBuffer();
    gl.bindBuffer(target, b);
    if (b.__bytes === data.byteLength) gl.bufferSubData(target, 0, data);
    else { gl.bufferData(target, data, gl.DYNAMIC_DRAW); b.__bytes = data.byteLength; }
    return b;
  }

  /** @this {Viewer} */
  _segmentVAO(segs, pool = /** @type {Viewer} */ (/** @type {unknown} */ (this))._pool(null)) {
    const gl = this.gl;
    const old = pool.parts.pop();
    const vao = old ? old.vao : gl.createVertexArray();
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, this.cornerBuf);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    const buf = this._buffer({ bufs: old ? old.buffers.slice() : [], ibufs: [] }, segs, gl.ARRAY_BUFFER);
    gl.enableVertexAttribArray(1);
    gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 24, 0);
    gl.vertexAttribDivisor(1, 1);
    gl.enableVertexAttribArray(2);
    gl.vertexAttribPointer(2, 3, gl.FLOAT, false, 24, 12);
    gl.vertexAttribDivisor(2, 1);
    gl.bindVertexArray(null);
    return { vao, buffers: [buf], count: segs.length / 6 };
  }

  /** @this {Viewer} */
  _upload(obj) {
    const gl = this.gl;
    const pool = this._pool(obj._reuse);
    obj._reuse = null;
    const buffer = (data, target = gl.ARRAY_BUFFER) => this._buffer(pool, data, target);
    const gpu = { parts: [] };
    if (obj.kind === 'mesh') {
      const vao = pool.main || gl.createVertexArray();
      pool.main = null;
      gl.bindVertexArray(vao);
      const pb = buffer(obj.positions);
      gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
      const nb = buffer(obj.normals);
      gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
      const bufs = [pb, nb];
      if (obj.scalars) {
        bufs.push(buffer(obj.scalars));
        gl.enableVertexAttribArray(2); gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 0, 0);
      } else {
        gl.disableVertexAttribArray(2);
      }
      // the triangles of a grid mesh do not change while its points move: the index buffer is kept when equal
      if (pool.ibufs.length && sameArray(pool.indices, obj.indices)) { gpu.ibuf = pool.ibufs.pop(); gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gpu.ibuf); }
      else gpu.ibuf = buffer(obj.indices, gl.ELEMENT_ARRAY_BUFFER);
      gpu.indices = obj.indices;
      gl.bindVertexArray(null);
      gpu.vao = vao; gpu.buffers = bufs; gpu.count = obj.indices.length;
      for (const ov of obj.overlays) gpu.parts.push({ ...this._segmentVAO(ov.segs, pool), style: ov });
    } else if (obj.kind === 'lines') {
      gpu.parts.push({ ...this._segmentVAO(obj.segs, pool), style: obj.style });
    } else if (obj.kind === 'points') {
      const vao = pool.main || gl.createVertexArray();
      pool.main = null;
      gl.bindVertexArray(vao);
      const pb = buffer(obj.positions);
      gl.enableVertexAttribArray(0); gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
      const bufs = [pb];
      if (obj.colors) {
        bufs.push(buffer(obj.colors));
        gl.enableVertexAttribArray(1); gl.vertexAttribPointer(1, 3, gl.FLOAT, false, 0, 0);
      } else gl.disableVertexAttribArray(1);
      gl.bindVertexArray(null);
      gpu.vao = vao; gpu.buffers = bufs; gpu.count = obj.positions.length / 3;
    }
    obj.gpu = gpu;
    // what the new upload did not take
    this._freeGpu({ vao: pool.main, buffers: pool.bufs.concat(pool.ibufs), parts: pool.parts });
  }

  /** @this {Viewer} */
  _free(obj) {
    const gpu = obj.gpu, reuse = obj._reuse;
    obj.gpu = null; obj._reuse = null;
    this._freeGpu(gpu);
    this._freeGpu(reuse);
  }

  /** @this {Viewer} */
  _freeGpu(gpu) {
    const gl = this.gl;
    if (!gl || !gpu || gl.isContextLost()) return;
    if (gpu.vao) gl.deleteVertexArray(gpu.vao);
    for (const b of gpu.buffers || []) gl.deleteBuffer(b);
    if (gpu.ibuf) gl.deleteBuffer(gpu.ibuf);
    for (const part of gpu.parts || []) { gl.deleteVertexArray(part.vao); part.buffers.forEach((b) => gl.deleteBuffer(b)); }
  }

  /** @this {Viewer} */
  renderNow() {
    if (this.destroyed) return;
    this._flushFit(); // (a fit() asked for before the first drawing: made now, before the canvas is measured)
    if (this._raf) { cancelAnimationFrame(this._raf); this._raf = 0; } // (this drawing is the one fit() asked for)
    const canvas = this.canvas;
    const dpr = Math.min(window.devicePixelRatio || 1, 2);
    const [cw, ch] = this._canvasSize();
    const W = Math.max(1, Math.round(cw * dpr)), H = Math.max(1, Math.round(ch * dpr));
    if (canvas.width !== W || canvas.height !== H) { canvas.width = W; canvas.height = H; }
    this._drawnSize = [cw, ch, dpr];
    this._updateScene();
    if (this._needsFit && this._sceneBox() && cw > 0) {
      this._needsFit = false;
      this._fitNow = true;
      try { this.fit(); } finally { this._fitNow = false; }
      // (fit() asked for a drawing: this is it; a canvas it resized is drawn again when the ResizeObserver reports)
      if (this._raf) { cancelAnimationFrame(this._raf); this._raf = 0; }
    }
    const gl = this.gl;
    if (!gl || gl.isContextLost()) { this._syncLabels(); return; }
    try { this._readyPrograms(); } catch (e) { console.error(e); this.gl = null; this._glError = e; this._showFallback(); this._syncLabels(); return; }
    const cam = this._camera();
    gl.viewport(0, 0, W, H);
    const bg = this.background;
    gl.clearColor(bg[0], bg[1], bg[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LEQUAL);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
    gl.disable(gl.CULL_FACE);

    const objs = [...this.objects.values()].filter((o) => o.visible).sort((a, b) => a.order - b.order);
    for (const o of objs) if (!o.gpu) this._upload(o);
    const meshes = objs.filter((o) => o.kind === 'mesh');
    const opaque = meshes.filter((o) => o.opacity >= 1), clear = meshes.filter((o) => o.opacity < 1);

    // surfaces (pushed back a little so lines lying on them win the depth test)
    const mp = this.prog.mesh;
    gl.useProgram(mp.p);
    gl.uniformMatrix4fv(mp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(mp.u.uProj, false, cam.proj);
    gl.uniform1i(mp.u.uMap, 0);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    const drawMesh = (o) => {
      gl.uniform3fv(mp.u.uColor, o.color);
      gl.uniform1f(mp.u.uOpacity, o.opacity);
      gl.uniform1i(mp.u.uUseMap, o.scalars ? 1 : 0);
      gl.uniform2f(mp.u.uRange, o.range ? o.range[0] : 0, o.range ? o.range[1] : 1);
      if (o.scalars) { gl.activeTexture(gl.TEXTURE0); gl.bindTexture(gl.TEXTURE_2D, this._mapTexture(o.colormap)); }
      gl.bindVertexArray(o.gpu.vao);
      if (!o.scalars) gl.vertexAttrib1f(2, 0);
      gl.drawElements(gl.TRIANGLES, o.gpu.count, gl.UNSIGNED_INT, 0);
    };
    gl.depthMask(true);
    opaque.forEach(drawMesh);
    gl.disable(gl.POLYGON_OFFSET_FILL);

    // lines: mesh overlays and line sets
    const lp = this.prog.line;
    gl.useProgram(lp.p);
    gl.uniformMatrix4fv(lp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(lp.u.uProj, false, cam.proj);
    gl.uniform2f(lp.u.uViewport, W, H);
    const drawPart = (part, bias) => {
      if (!part.count) return;
      const s = part.style;
      gl.uniform1f(lp.u.uWidth, s.width * dpr);
      gl.uniform1f(lp.u.uBias, bias);
      gl.uniform4f(lp.u.uColor, s.color[0], s.color[1], s.color[2], s.alpha);
      gl.bindVertexArray(part.vao);
      gl.drawArraysInstanced(gl.TRIANGLES, 0, 6, part.count);
    };
    for (const o of objs) {
      if (o.kind === 'mesh' && o.opacity >= 1) o.gpu.parts.forEach((p) => drawPart(p, 0.0005));
      if (o.kind === 'lines') o.gpu.parts.forEach((p) => drawPart(p, 0.001));
    }

    // translucent surfaces: no depth writes, drawn after everything opaque
    if (clear.length) {
      gl.useProgram(mp.p);
      gl.depthMask(false);
      clear.forEach(drawMesh);
      gl.useProgram(lp.p);
      for (const o of clear) o.gpu.parts.forEach((p) => drawPart(p, 0.0005));
      gl.depthMask(true);
    }

    // points
    const pp = this.prog.point;
    gl.useProgram(pp.p);
    gl.uniformMatrix4fv(pp.u.uView, false, cam.view);
    gl.uniformMatrix4fv(pp.u.uProj, false, cam.proj);
    const hl = this.dragging || this.selected || this.hover;
    for (const [id, o] of this.objects) {
      if (o.kind !== 'points' || !o.visible || !o.gpu.count) continue;
      if (o.onTop) gl.disable(gl.DEPTH_TEST); else gl.enable(gl.DEPTH_TEST);
      gl.bindVertexArray(o.gpu.vao);
      if (!o.colors) gl.vertexAttrib3fv(1, o.color);
      const size = Math.min(o.size * dpr, this.maxPointSize);
      gl.uniform1f(pp.u.uSize, size);
      gl.uniform1f(pp.u.uHighlight, 0);
      gl.drawArrays(gl.POINTS, 0, o.gpu.count);
      if (hl && hl.id === id && hl.index < o.gpu.count) {
        gl.uniform1f(pp.u.uSize, Math.min(size * 1.45, this.maxPointSize));
        gl.uniform1f(pp.u.uHighlight, 1);
        gl.drawArrays(gl.POINTS, hl.index, 1);
      }
    }
    gl.enable(gl.DEPTH_TEST);
    gl.bindVertexArray(null);
    this._drawAxes(cam, cw, ch, dpr);
    this._syncLabels(cam);
  }
}
