# The page's plotly.js bundle, installed exactly as package-lock.json pins it.
FROM node:20-slim AS assets
WORKDIR /app
COPY package.json package-lock.json ./
RUN npm ci --ignore-scripts --no-audit --no-fund

FROM python:3.11-slim
WORKDIR /app
COPY requirements.lock ./
RUN pip install --no-cache-dir --require-hashes --no-deps -r requirements.lock
COPY . .
COPY --from=assets /app/node_modules ./node_modules
ENV PYTHONPATH=/app/backend
CMD ["sh", "-c", "python -m actuator_selection migrate && python -m actuator_selection seed --if-empty && python -m actuator_selection serve"]
