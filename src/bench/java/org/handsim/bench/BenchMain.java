package org.handsim.bench;
public class BenchMain { public static void main(String[] a){ System.out.println("bench"); } }
