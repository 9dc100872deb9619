# The service's image: runtime dependencies only, a non-root user, a healthcheck, several
# worker processes. Migrations run once, before the replicas start, in docker-compose.yml's
# `migrate` service (the same image with another command).

# The page's plotly.js bundle, installed exactly as package-lock.json pins it (not the
# browser tests' axe-core, a dev dependency).
FROM node:20-slim AS assets
WORKDIR /app
COPY package.json package-lock.json ./
RUN npm ci --omit=dev --ignore-scripts --no-audit --no-fund

FROM python:3.11-slim
RUN useradd --create-home --uid 10001 --shell /usr/sbin/nologin app
# DejaVu Sans for the PDFs (quote document, selection report): every character of the
# chapter (min⁻¹, ≤, T₁) and €; without it they fall back to Latin-1 Helvetica.
RUN apt-get update \
 && apt-get install --yes --no-install-recommends fonts-dejavu-core \
 && rm -rf /var/lib/apt/lists/*
WORKDIR /app
# requirements-runtime.lock: the hash-pinned runtime dependencies (no test tools).
COPY requirements-runtime.lock ./
RUN pip install --no-cache-dir --require-hashes --no-deps -r requirements-runtime.lock
COPY alembic.ini ./
COPY backend ./backend
COPY frontend ./frontend
COPY migrations ./migrations
COPY seed_data ./seed_data
COPY --from=assets /app/node_modules ./node_modules
ENV PYTHONPATH=/app/backend \
    PYTHONDONTWRITEBYTECODE=1 \
    HOST=0.0.0.0 \
    PORT=8000 \
    WORKERS=2
# DATA_DIR: the document links' signing secret, made at the first start
# (docker-compose.yml shares it between the replicas as a volume).
RUN mkdir -p /app/var && chown app:app /app/var
USER app
EXPOSE 8000
HEALTHCHECK --interval=10s --timeout=3s --start-period=20s --retries=3 \
  CMD ["python", "-c", "import os, urllib.request; urllib.request.urlopen('http://127.0.0.1:%s/api/v1/health' % os.environ['PORT'], timeout=2)"]
CMD ["python", "-m", "actuator_selection", "serve"]
