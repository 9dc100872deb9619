FROM python:3.11-slim
WORKDIR /app
COPY requirements.lock ./
RUN pip install --no-cache-dir --require-hashes --no-deps -r requirements.lock
COPY . .
ENV PYTHONPATH=/app/backend
CMD ["sh", "-c", "python -m actuator_selection migrate && python -m actuator_selection seed --if-empty && python -m actuator_selection serve"]
