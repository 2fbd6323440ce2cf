// What the front end (www/) adds to the browser's own objects, declared for its type check (www/jsconfig.json).
// Each is set in one place and read by the shell, exporters and tests.

declare global {
  interface Window {
    /** The playground's test and automation hooks (www/app.js, www/lib/storage-notice.js). */
    splinelab?: any;
    /** The offline file's hooks (www/lib/offline.js). */
    splinelabOffline?: any;
    /** The sandbox page's hooks (www/sandbox.js). */
    splinelabSandbox?: any;
    /** The compute client's hooks (www/lib/compute-client.js). */
    splinelabCompute?: any;
    /** Wasm fetches started by www/lib/wasm-preload.js, taken by www/lib/host.js (URL → Response promise). */
    __splinelabWasmFetch?: Map<string, Promise<Response> | null>;
    /** The developers' page www/dev/view3d-demo.js: its views, for the console. */
    __view?: any;
    __view2?: any;
    __view3?: any;
  }
  interface HTMLCanvasElement {
    /** The 2D plot drawn on this canvas (www/lib/plot2d.js), for the exporters and tests. */
    splinePlot?: any;
    /** The 3D view drawn on this canvas (www/lib/view3d.js), for the exporters and tests. */
    view3d?: any;
    /** The view of www/demos/curve-networks.js, for tests and course authors' scripts. */
    splineView?: any;
  }
  interface HTMLElement {
    /** A colour-bar legend's parts (www/lib/colormap.js). */
    _parts?: any;
    /** The Export row's menu list (www/lib/demo-export.js). */
    _list?: any[];
    /** The Export row's last written file, for tests (www/lib/demo-export.js). */
    lastExport?: any;
    /** The last copied snippet, for tests (www/lib/snippet.js). */
    lastSnippet?: string;
  }
}
export {};

declare global {
  /** The sandbox worker's hand-over of the visitor's code, loaded as a classic script (www/sandbox-worker.js). */
  var __splinelabSandbox: ((id: number, fn: Function) => void) | undefined;
}

declare global {
  interface ArrayBufferConstructor {
    /** www/ passes typed arrays here, never a DataView: narrowed to the typed arrays it uses. */
    isView(arg: any): arg is Float64Array | Float32Array | Uint32Array | Uint16Array | Uint8Array | Int32Array;
  }
}
