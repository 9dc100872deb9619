// plotly.js, served by the app itself (no CDN).
//
// The engineer's page names the versioned bundle in its <head> as
// <script defer data-plotly src="/vendor/plotly-basic-….min.js">, after the page's
// module: the browser fetches it while the page loads, and runs it after the page's
// module has run, so the form is usable first and this module's listeners are in
// place before the script's load or error event. Without that tag (or when it fails,
// e.g. a page cached from before an upgrade naming a version the server no longer
// has) the bundle's current URL is asked of /vendor/plotly.js.

import { ApiError, createClient } from "./api.js";

const vendor = createClient({ base: "" });
let pending = null;

function settled(script) {
  return new Promise((resolve) => {
    script.addEventListener("load", () => resolve(true), { once: true });
    script.addEventListener("error", () => resolve(false), { once: true });
  });
}

function inject(url) {
  const script = document.createElement("script");
  script.src = url;
  script.async = true;
  const done = settled(script);
  document.head.append(script);
  return done;
}

// Listened to as this module is evaluated, before the deferred bundle runs.
const tag = document.querySelector("script[data-plotly]");
const fromTag = tag ? settled(tag) : Promise.resolve(false);

async function load() {
  if ((await fromTag) && window.Plotly) return window.Plotly;
  const where = await vendor.get("/vendor/plotly.js");
  if (typeof where.url !== "string" || !where.url.startsWith("/")) {
    throw new ApiError({ status: 200, kind: "bad_response" });
  }
  if (!(await inject(where.url))) throw new ApiError({ status: 0, kind: "network" });
  if (!window.Plotly) throw new ApiError({ status: 200, kind: "bad_response" });
  return window.Plotly;
}

/** window.Plotly once the bundle has run; one attempt at a time, another after a failure. */
export function loadPlotly() {
  if (window.Plotly) return Promise.resolve(window.Plotly);
  if (!pending) {
    pending = load();
    pending.catch(() => {
      pending = null; // a later chart may try again
    });
  }
  return pending;
}
