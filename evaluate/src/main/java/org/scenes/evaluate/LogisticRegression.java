package org.scenes.evaluate;

import java.util.List;

/**
 * Binary logistic regression on standardised features, fitted by full-batch gradient descent with
 * a small L2 penalty: the simplest classifier that a linear difference between two players'
 * windows cannot escape. Deterministic (no random start), so figures repeat.
 */
final class LogisticRegression {
    private static final int ITERATIONS = 400;
    private static final double RATE = 0.5;
    private static final double L2 = 1e-3;

    private final double[] mean;
    private final double[] scale;
    private final double[] weights;
    private final double bias;

    private LogisticRegression(double[] mean, double[] scale, double[] weights, double bias) {
        this.mean = mean;
        this.scale = scale;
        this.weights = weights;
        this.bias = bias;
    }

    /** Fits class 0 ({@code negatives}) against class 1 ({@code positives}), each class weighted equally. */
    static LogisticRegression fit(List<double[]> negatives, List<double[]> positives) {
        int d = negatives.get(0).length;
        double[] mean = new double[d];
        double[] scale = new double[d];
        int n = negatives.size() + positives.size();
        for (List<double[]> group : List.of(negatives, positives)) {
            for (double[] x : group) {
                for (int j = 0; j < d; j++) {
                    mean[j] += x[j] / n;
                }
            }
        }
        for (List<double[]> group : List.of(negatives, positives)) {
            for (double[] x : group) {
                for (int j = 0; j < d; j++) {
                    scale[j] += (x[j] - mean[j]) * (x[j] - mean[j]) / n;
                }
            }
        }
        for (int j = 0; j < d; j++) {
            scale[j] = scale[j] > 1e-12 ? Math.sqrt(scale[j]) : 1;
        }
        double[] w = new double[d];
        double b = 0;
        double weightNegative = 0.5 / negatives.size();
        double weightPositive = 0.5 / positives.size();
        double[] z = new double[d];
        for (int iteration = 0; iteration < ITERATIONS; iteration++) {
            double[] gradient = new double[d];
            double gradientBias = 0;
            for (int label = 0; label < 2; label++) {
                List<double[]> group = label == 0 ? negatives : positives;
                double weight = label == 0 ? weightNegative : weightPositive;
                for (double[] x : group) {
                    standardise(x, mean, scale, z);
                    double error = (sigmoid(dot(w, z) + b) - label) * weight;
                    for (int j = 0; j < d; j++) {
                        gradient[j] += error * z[j];
                    }
                    gradientBias += error;
                }
            }
            for (int j = 0; j < d; j++) {
                w[j] -= RATE * (gradient[j] + L2 * w[j]);
            }
            b -= RATE * gradientBias;
        }
        return new LogisticRegression(mean, scale, w, b);
    }

    /** The probability that {@code x} belongs to the positive class. */
    double probability(double[] x) {
        double[] z = new double[x.length];
        standardise(x, mean, scale, z);
        return sigmoid(dot(weights, z) + bias);
    }

    private static void standardise(double[] x, double[] mean, double[] scale, double[] z) {
        for (int j = 0; j < x.length; j++) {
            z[j] = (x[j] - mean[j]) / scale[j];
        }
    }

    private static double dot(double[] a, double[] b) {
        double sum = 0;
        for (int j = 0; j < a.length; j++) {
            sum += a[j] * b[j];
        }
        return sum;
    }

    private static double sigmoid(double t) {
        return 1 / (1 + Math.exp(-t));
    }
}
