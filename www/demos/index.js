// The demos of the gallery, in gallery order. Each id is a module www/demos/<id>.js (see README.md).
export const DEMO_IDS = [
  'bspline-basics',
  'interp-approx',
  'noisy-data',
  'b2-surfaces',
  'quasi-cubic-curves',
  'blended-interpolation',
  'quasi-cubic-surfaces',
  'curve-networks',
  'criss-cross-basis',
  'bezier-remodel',
  'knot-modification',
];
