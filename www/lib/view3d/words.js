// The camera of a 3D view in words, for the live region (issue 25): "view from the south-west, 30° above; zoom 1.5×".
// Compass directions take x as east and y as north (the HELP text says so).

import { DEG } from './constants.js';

const COMPASS = ['east', 'north-east', 'north', 'north-west', 'west', 'south-west', 'south', 'south-east'];

/**
 * @param {number} yaw    the camera's azimuth (radians; the eye sits at angle `yaw` from +x around the target)
 * @param {number} pitch  its elevation (radians, − below)
 * @param {number} zoom   how much closer than the framed view (1 = framed)
 */
export function viewWords(yaw, pitch, zoom) {
  const az = (((yaw / DEG) % 360) + 360) % 360;
  const el = Math.round(pitch / DEG);
  const from = Math.abs(el) >= 85 ? `from directly ${el > 0 ? 'above' : 'below'}`
    : `from the ${COMPASS[Math.round(az / 45) % 8]}, ${Math.abs(el)}° ${el >= 0 ? 'above' : 'below'}`;
  const z = Number.isFinite(zoom) && zoom > 0 ? Number(zoom.toPrecision(zoom < 10 ? 2 : 3)) : 1;
  return `view ${from}; zoom ${z}×`;
}
