// The page's only way to the server: the public /api/v1 endpoints and the
// locally served plotly.js. Every failure becomes an ApiError, never an
// exception text or stack trace on the page.

const API = "/api/v1";

/** A failed request: HTTP status (0 when the server was not reached) and what it said. */
export class ApiError extends Error {
  constructor({ status, fieldErrors = [], detail = null, kind = "http" }) {
    super(detail ?? `HTTP ${status}`);
    this.name = "ApiError";
    this.status = status;
    /** [{loc: [...], msg, type}] from a 422 body */
    this.fieldErrors = fieldErrors;
    /** the text of a {"detail": "..."} body */
    this.detail = detail;
    /** "http", "network" or "bad_response" */
    this.kind = kind;
  }
}

function parseErrorBody(status, data) {
  const detail = data && typeof data === "object" ? data.detail : undefined;
  if (Array.isArray(detail)) {
    const fieldErrors = detail
      .filter((e) => e && typeof e === "object" && Array.isArray(e.loc))
      .map((e) => ({ loc: e.loc, msg: String(e.msg ?? ""), type: String(e.type ?? "") }));
    // a 404 from a domain error carries one entry; its message is the detail
    const text = status === 404 && fieldErrors.length ? fieldErrors[0].msg : null;
    return new ApiError({ status, fieldErrors, detail: text });
  }
  if (typeof detail === "string") return new ApiError({ status, detail });
  return new ApiError({ status });
}

async function request(method, path, body) {
  const init = { method, headers: { Accept: "application/json" } };
  if (body !== undefined) {
    init.headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  let response;
  try {
    response = await fetch(path, init);
  } catch {
    throw new ApiError({ status: 0, kind: "network" });
  }
  let data = null;
  try {
    const text = await response.text();
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) throw parseErrorBody(response.status, data);
  if (data === null || typeof data !== "object") {
    throw new ApiError({ status: response.status, kind: "bad_response" });
  }
  return data;
}

/** POST /api/v1/selections: run and store a selection. */
export function createSelection(body) {
  return request("POST", `${API}/selections`, body);
}

/** GET /api/v1/selections/{id}: a stored selection. */
export function getSelection(id) {
  return request("GET", `${API}/selections/${encodeURIComponent(id)}`);
}

const actuators = new Map();

/** GET /api/v1/actuators/{model}, remembered for the page's lifetime (catalogue data). */
export function getActuator(model) {
  if (!actuators.has(model)) {
    const pending = request("GET", `${API}/actuators/${encodeURIComponent(model)}`);
    pending.catch(() => actuators.delete(model));
    actuators.set(model, pending);
  }
  return actuators.get(model);
}

let plotly = null;

/** window.Plotly from the app's own /vendor/plotly.js location (no CDN), loaded once. */
export function loadPlotly() {
  if (window.Plotly) return Promise.resolve(window.Plotly);
  if (!plotly) {
    plotly = (async () => {
      const where = await request("GET", "/vendor/plotly.js");
      if (typeof where.url !== "string" || !where.url.startsWith("/")) {
        throw new ApiError({ status: 200, kind: "bad_response" });
      }
      await new Promise((resolve, reject) => {
        const script = document.createElement("script");
        script.src = where.url;
        script.async = true;
        script.onload = resolve;
        script.onerror = () => reject(new ApiError({ status: 0, kind: "network" }));
        document.head.append(script);
      });
      if (!window.Plotly) throw new ApiError({ status: 200, kind: "bad_response" });
      return window.Plotly;
    })();
    plotly.catch(() => {
      plotly = null; // a later chart may try again
    });
  }
  return plotly;
}
